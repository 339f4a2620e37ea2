"""Builds the compiled part of `momentlab` with CMake (pyproject.toml has the metadata).

The extension is the CMake target `_momentlab` (python/CMakeLists.txt), configured with the
library linked in statically, so the installed package needs no other file of this checkout.
MOMENTLAB_CMAKE_BUILD_DIR (default build/python-wheel) keeps the CMake build between installs;
MOMENTLAB_JOBS (default 2) is its parallelism.
"""

import os
import shutil
import subprocess
import sys
from pathlib import Path

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = Path(__file__).resolve().parent


class CMakeExtension(Extension):
    def __init__(self, name):
        super().__init__(name, sources=[])


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        build_dir = Path(os.environ.get("MOMENTLAB_CMAKE_BUILD_DIR", ROOT / "build" / "python-wheel")).resolve()
        jobs = os.environ.get("MOMENTLAB_JOBS", "2")
        subprocess.run(["cmake", "-S", str(ROOT), "-B", str(build_dir), "-DCMAKE_BUILD_TYPE=Release",
                        "-DBUILD_SHARED_LIBS=OFF", "-DMOMENTLAB_TESTS=OFF", "-DMOMENTLAB_PYTHON=ON",
                        # a unity build, as the Makefile's trees: ccache then serves their objects
                        "-DCMAKE_UNITY_BUILD=ON",
                        f"-DPython_EXECUTABLE={sys.executable}"]
                       # ccache, when there is one, serves the objects a build of this checkout made.
                       + (["-DCMAKE_CXX_COMPILER_LAUNCHER=ccache"] if shutil.which("ccache") else []), check=True)
        subprocess.run(["cmake", "--build", str(build_dir), "--target", "_momentlab", f"-j{jobs}"], check=True)
        built = next((build_dir / "python" / "momentlab").glob("_momentlab*.so"))
        target = Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(built, target)


setup(ext_modules=[CMakeExtension("momentlab._momentlab")], cmdclass={"build_ext": CMakeBuild})
