# SPDX-License-Identifier: GPL-3.0-or-later
"""The Python module's build for pip (pyproject.toml): CMake builds the extension sculpt._sculpt
and the headless rendering module for the interpreter pip runs, optimised and stripped, and both
go into the package (the extension finds the rendering module beside itself)."""
import os
import shutil
import subprocess
import sys
import sysconfig
from pathlib import Path

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

SOURCE = Path(__file__).resolve().parent


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        # A build folder beside build/ and the same flags as scripts/build: ccache (paths
        # relative to the source) reuses what a build of the tree made.
        build = Path(os.environ.get("SCULPT_PYTHON_BUILD_DIR", SOURCE / "build-python"))
        environment = dict(os.environ, CCACHE_BASEDIR=str(SOURCE), CCACHE_NOHASHDIR="1")
        subprocess.run(
            ["cmake", "-S", str(SOURCE), "-B", str(build), "-G", "Ninja",
             "-DCMAKE_BUILD_TYPE=RelWithDebInfo", f"-DPython3_EXECUTABLE={sys.executable}",
             "-DSCULPT_BUILD_TESTS=OFF", "-DSCULPT_BUILD_VIEWER=OFF"],
            check=True, env=environment, stdout=subprocess.DEVNULL)
        subprocess.run(["cmake", "--build", str(build), "--target", "sculpt_python", "sculpt_osmesa",
                        "--parallel", os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL", "2")],
                       check=True, env=environment)
        extension = Path(self.get_ext_fullpath(ext.name))
        extension.parent.mkdir(parents=True, exist_ok=True)
        # This interpreter's module (a build for another version may be there too).
        built = build / "python" / "sculpt" / ("_sculpt" + sysconfig.get_config_var("EXT_SUFFIX"))
        shutil.copyfile(built, extension)
        renderer = extension.parent / "libsculpt_osmesa.so"
        shutil.copyfile(build / "libsculpt_osmesa.so", renderer)
        # Installed without debug information: a few MB instead of tens.
        subprocess.run(["strip", "--strip-unneeded", str(extension), str(renderer)], check=True)


setup(ext_modules=[Extension("sculpt._sculpt", sources=[])],
      cmdclass={"build_ext": CMakeBuild})
