"""Builds c2f._c2f with the project's CMake for `pip install --no-build-isolation .`

The extension module is the CMake target c2f_python (python/CMakeLists.txt), configured for the
interpreter that runs pip, with the tools, tests and benchmarks off; the package's Python files
come from python/c2f (pyproject.toml).
"""

import os
import pathlib
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext


def pybind11_location() -> list:
    """-Dpybind11_DIR for CMake when the building interpreter has a pybind11 package that carries
    its CMake files (pip's pybind11 in an isolated build); Debian's are found by CMake itself."""
    try:
        import pybind11
    except ImportError:
        return []
    directory = pathlib.Path(pybind11.get_cmake_dir())
    return [f"-Dpybind11_DIR={directory}"] if (directory / "pybind11Config.cmake").exists() else []


class CMakeExtension(Extension):
    def __init__(self, name: str) -> None:
        super().__init__(name, sources=[])


class CMakeBuild(build_ext):
    def build_extension(self, ext: Extension) -> None:
        source = pathlib.Path(__file__).parent.resolve()
        build = pathlib.Path(self.build_temp).resolve() / "cmake"
        target = pathlib.Path(self.get_ext_fullpath(ext.name)).resolve()
        build.mkdir(parents=True, exist_ok=True)
        configure = [
            "cmake", "-S", str(source), "-B", str(build), "-G", "Ninja",
            "-DCMAKE_BUILD_TYPE=Release", f"-DPython3_EXECUTABLE={sys.executable}",
            "-DC2F_PYTHON=ON", "-DC2F_BUILD_TESTS=OFF", "-DC2F_BUILD_EXAMPLES=OFF",
            "-DC2F_BUILD_BENCHMARKS=OFF", "-DC2F_BUILD_FUZZERS=OFF", "-DC2F_INSTALL=OFF",
        ]
        configure += pybind11_location()
        subprocess.run(configure, check=True)
        jobs = os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL", str(os.cpu_count() or 1))
        subprocess.run(["cmake", "--build", str(build), "--target", "c2f_python", "-j", jobs],
                       check=True)
        built = next((build / "python" / "c2f").glob("_c2f*.so"))
        target.parent.mkdir(parents=True, exist_ok=True)
        self.copy_file(str(built), str(target))


setup(ext_modules=[CMakeExtension("c2f._c2f")], cmdclass={"build_ext": CMakeBuild})
