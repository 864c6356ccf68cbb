"""Builds the extension softgl._softgl with this project's CMake (SOFTGL_BUILD_PYTHON), for pip.

    pip install --no-build-isolation .

The build needs cmake, a C++20 compiler, and Debian's pybind11-dev, python3-dev, python3-numpy, libglm-dev,
libassimp-dev, libstb-dev, libjpeg62-turbo-dev and libcli11-dev (scripts/deps.sh installs them); nothing is
downloaded. SOFTGL_CMAKE_ARGS adds arguments to the configure step.
"""
import os
import shlex
import subprocess
import sys
from pathlib import Path

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = Path(__file__).resolve().parent


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        out = Path(self.get_ext_fullpath(ext.name)).resolve().parent.parent  # the folder that holds softgl/
        build = Path(self.build_temp).resolve() / "cmake"
        configure = [
            "cmake", "-S", str(ROOT), "-B", str(build), "-DCMAKE_BUILD_TYPE=Release",
            "-DSOFTGL_BUILD_PYTHON=ON", "-DSOFTGL_BUILD_TESTS=OFF", "-DSOFTGL_BUILD_EXAMPLES=OFF",
            "-DSOFTGL_INSTALL=OFF", f"-DPython_EXECUTABLE={sys.executable}",
            f"-DSOFTGL_PYTHON_OUTPUT_DIR={out}",
        ] + shlex.split(os.environ.get("SOFTGL_CMAKE_ARGS", ""))
        subprocess.run(configure, check=True)
        jobs = str(os.cpu_count() or 1)
        subprocess.run(["cmake", "--build", str(build), "--target", "softgl_python", "-j", jobs], check=True)


setup(ext_modules=[Extension("softgl._softgl", sources=[])], cmdclass={"build_ext": CMakeBuild})
