"""Builds the Python module with CMake, for `pip install .` and `python3 -m build` (see
pyproject.toml). The compiled core comes from this tree's CMakeLists.txt with only the
library and the module switched on; the pure-Python part from python/pcskeleton.

CMAKE_ARGS in the environment is passed on to CMake, e.g.
CMAKE_ARGS="-DMESHLAB_SOURCE_DIR=/path/to/meshlab" for a MeshLab source tree (vcglib) other
than the one scripts/setup.sh unpacks.
"""

import os
import re
import shlex
import shutil
import subprocess
import sys
from pathlib import Path

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = Path(__file__).resolve().parent


def project_version():
    text = (ROOT / "CMakeLists.txt").read_text()
    match = re.search(r"project\(pcskeleton VERSION ([0-9.]+)", text)
    if not match:
        sys.exit("setup.py: no project(pcskeleton VERSION ...) in CMakeLists.txt")
    return match.group(1)


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        build = Path(self.build_temp).resolve() / "cmake"
        configure = [
            "cmake", "-S", str(ROOT), "-B", str(build),
            "-DCMAKE_BUILD_TYPE=Release",
            f"-DPython3_EXECUTABLE={sys.executable}",
            "-DPCSKELETON_BUILD_PYTHON=ON",
            "-DPCSKELETON_BUILD_PLUGINS=OFF",
            "-DPCSKELETON_BUILD_TESTS=OFF",
            "-DPCSKELETON_BUILD_BENCH=OFF",
        ] + shlex.split(os.environ.get("CMAKE_ARGS", ""))
        if shutil.which("cmake") is None:
            sys.exit("setup.py: cmake is not installed (sudo apt install cmake)")
        subprocess.run(configure, check=True)
        jobs = str(os.cpu_count() or 1)
        subprocess.run(["cmake", "--build", str(build), "--target", "pcskeleton_python", "-j", jobs], check=True)
        built = list((build / "python" / "pcskeleton").glob("_pcskeleton*.so"))
        if len(built) != 1:
            sys.exit(f"setup.py: expected one compiled module in {build / 'python' / 'pcskeleton'}, found {built}")
        target = Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(built[0], target)


setup(
    version=project_version(),
    packages=["pcskeleton"],
    package_dir={"": "python"},
    ext_modules=[Extension("pcskeleton._pcskeleton", sources=[])],
    cmdclass={"build_ext": CMakeBuild},
    zip_safe=False,
)
