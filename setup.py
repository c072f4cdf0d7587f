"""pip's build of the Python module: CMake configures a Release build of the library and the
module alone (build/pip), and the package folder it makes, with the robots and tasks, becomes the
wheel's `pmdplan` package. Offline: `pip install --no-build-isolation .` (docs/python.md)."""
import os
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = os.path.dirname(os.path.abspath(__file__))


class CMakeBuild(build_ext):
    def build_extension(self, ext):
        build = os.path.join(ROOT, "build", "pip")
        subprocess.check_call([
            "cmake", "-S", ROOT, "-B", build, "-DCMAKE_BUILD_TYPE=Release", "-DPMDPLAN_BUILD_TESTS=OFF",
            "-DPMDPLAN_BUILD_BENCH=OFF", "-DPMDPLAN_BUILD_PYTHON=ON", f"-DPython_EXECUTABLE={sys.executable}",
            # Another compiler's new warnings must not stop a user's install (CI builds with -Werror).
            "-DPMDPLAN_WERROR=OFF",
        ])
        subprocess.check_call(["cmake", "--build", build, "--target", "pmdplan_python", "-j", str(os.cpu_count() or 1)])
        package = os.path.join(os.path.abspath(self.build_lib), "pmdplan")
        shutil.copytree(os.path.join(build, "python", "pmdplan"), package, dirs_exist_ok=True)
        shutil.copytree(os.path.join(ROOT, "data"), os.path.join(package, "data"), dirs_exist_ok=True)


setup(
    packages=[],
    ext_modules=[Extension("pmdplan._core", sources=[])],
    cmdclass={"build_ext": CMakeBuild},
    zip_safe=False,
)
