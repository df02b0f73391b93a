# SPDX-License-Identifier: GPL-3.0-or-later
"""Every example of examples/python runs headless and writes what it says."""
import os
import subprocess
import sys

import pytest


def run_example(examples_dir, name, *arguments, cwd):
    return subprocess.run([sys.executable, os.path.join(examples_dir, name), *arguments],
                          cwd=cwd, capture_output=True, text=True,
                          env={**os.environ, "MPLBACKEND": "Agg"})


@pytest.mark.parametrize("name, output", [("voronoi_and_poles.py", "voronoi_and_poles.png"),
                                          ("replay_separation.py", "replay.png")])
def test_a_lesson_draws_its_picture(examples_dir, name, output, tmp_path):
    run = run_example(examples_dir, name, cwd=tmp_path)
    assert run.returncode == 0, run.stderr
    with open(tmp_path / output, "rb") as picture:
        assert picture.read(8) == b"\x89PNG\r\n\x1a\n"


def test_a_scan_becomes_an_stl_with_its_verdict(examples_dir, tmp_path):
    run = run_example(examples_dir, "scan_to_stl.py", "-o", "bumpy.stl", cwd=tmp_path)
    assert run.returncode == 0, run.stderr
    assert "verdict: closed 2-manifold" in run.stdout
    assert (tmp_path / "bumpy.stl").stat().st_size > 84


def test_a_broken_result_exits_non_zero(examples_dir, tmp_path):
    # The alpha shape of the bumpy sphere leaves samples inside its solid: not a manifold through
    # every sample, so the script says so and fails.
    run = run_example(examples_dir, "scan_to_stl.py", "--method", "alpha-shape", cwd=tmp_path)
    assert run.returncode == 1
    assert "verdict: " in run.stdout and "closed 2-manifold of genus 0: 1 component" not in run.stdout


def test_an_unreadable_file_is_one_line(examples_dir, tmp_path):
    (tmp_path / "bad.xyz").write_text("1 2 three\n")
    run = run_example(examples_dir, "scan_to_stl.py", "bad.xyz", cwd=tmp_path)
    assert run.returncode == 1
    assert run.stderr.count("\n") == 1 and run.stderr.startswith("scan_to_stl: error: ")
