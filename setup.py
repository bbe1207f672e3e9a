# SPDX-License-Identifier: MIT
"""Builds the Python package `collide` (python/collide) with CMake: the extension module _collide
and the modules it opens (collide-gl.so, collide-vector.so, collide-video.so) go into the package
folder beside the pure-Python files. The build tree is build/pip (COLLIDE_BUILD_DIR to change it);
CMAKE_CXX_COMPILER_LAUNCHER=ccache is honoured as by scripts/setup."""
import os
import re
import shutil
import subprocess
import sys
from pathlib import Path

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = Path(__file__).resolve().parent
MODULES = ("collide-gl.so", "collide-vector.so", "collide-video.so")


def project_version() -> str:
    text = (ROOT / "CMakeLists.txt").read_text()
    return re.search(r"project\(collide VERSION ([0-9.]+)", text).group(1)


class CMakeBuild(build_ext):
    def build_extension(self, ext: Extension) -> None:
        build_dir = Path(os.environ.get("COLLIDE_BUILD_DIR", ROOT / "build" / "pip"))
        subprocess.run(["cmake", "-S", str(ROOT), "-B", str(build_dir), "-DCMAKE_BUILD_TYPE=Release",
                        "-DBUILD_TESTING=OFF", "-DCOLLIDE_PYTHON=ON",
                        f"-DPython_EXECUTABLE={sys.executable}"], check=True)
        jobs = str(os.cpu_count() or 1)
        subprocess.run(["cmake", "--build", str(build_dir), "-j", jobs, "--target",
                        "collide_python"], check=True)
        built = build_dir / "python" / "collide"
        target = Path(self.get_ext_fullpath(ext.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copy2(next(built.glob("_collide*.so")), target)
        for module in MODULES:
            shutil.copy2(build_dir / module, target.parent / module)


# setuptools' own files (egg-info, its build folders) under build/pip too, not in the checkout.
(ROOT / "build" / "pip").mkdir(parents=True, exist_ok=True)

setup(
    version=project_version(),
    options={"build": {"build_base": "build/pip/setuptools"}, "egg_info": {"egg_base": "build/pip"}},
    packages=["collide"],
    package_dir={"collide": "python/collide"},
    package_data={"collide": ["py.typed", "*.pyi"]},
    ext_modules=[Extension("collide._collide", sources=[])],
    cmdclass={"build_ext": CMakeBuild},
    zip_safe=False,
)
