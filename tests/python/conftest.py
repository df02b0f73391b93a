# SPDX-License-Identifier: GPL-3.0-or-later
"""The Python suite runs from ctest (tests/CMakeLists.txt), which puts the build's package on
PYTHONPATH and names the command line and the examples folder in the environment."""
import os
import subprocess

import pytest


def _required(name):
    value = os.environ.get(name)
    if not value:  # never skip silently: a run without them is a broken set-up
        raise RuntimeError(f"{name} is not set: run the Python suite through ctest")
    return value


@pytest.fixture(scope="session")
def sculpt_cli():
    """Runs the `sculpt` command line; returns the completed process (text output)."""
    executable = _required("SCULPT_EXECUTABLE")

    def run(*arguments):
        return subprocess.run([executable, *map(str, arguments)], capture_output=True, text=True)

    return run


@pytest.fixture(scope="session")
def examples_dir():
    return _required("SCULPT_PYTHON_EXAMPLES")
