"""`pip install .`: the facet Python module (`import facet`), built by CMake from python/.

No network and nothing downloaded: there is no pyproject.toml, so pip builds with the
setuptools, wheel and pybind11 already installed (Debian's python3-setuptools,
python3-wheel, pybind11-dev), without build isolation. PEP 668 keeps pip out of Debian's own
Python; use a virtual environment that sees Debian's NumPy:

    python3 -m venv --system-site-packages ~/venvs/facet
    ~/venvs/facet/bin/pip install --no-build-isolation .

The module links an installed facet of this version when CMake finds one: FACET_PREFIX=/prefix
(added to CMAKE_PREFIX_PATH), or CMAKE_PREFIX_PATH itself. Otherwise facet's libraries are
built from this source tree too (slower). Other environment variables:
    FACET_PYTHON_BUILD_DIR   where the build goes (default: build-python/ in the source tree)
    CMAKE_BUILD_PARALLEL_LEVEL  compile jobs (default: the number of cores)
    CMAKE_GENERATOR, CMAKE_CXX_COMPILER_LAUNCHER, ...  as CMake reads them
"""
import os
import pathlib
import re
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

ROOT = pathlib.Path(__file__).resolve().parent
BUILD_BASE = pathlib.Path(os.environ.get("FACET_PYTHON_BUILD_DIR", ROOT / "build-python")).resolve()


def version():
    match = re.search(r"project\(facet VERSION ([0-9.]+)", (ROOT / "CMakeLists.txt").read_text())
    if not match:
        sys.exit("setup.py: no 'project(facet VERSION x.y.z' in CMakeLists.txt")
    return match.group(1)


class CMakeExtension(Extension):
    """The compiled module facet._facet, which CMake builds (python/CMakeLists.txt)."""

    def __init__(self):
        super().__init__("facet._facet", sources=[])


class BuildWithCMake(build_ext):
    def build_extension(self, extension):
        build_dir = BUILD_BASE / "cmake"
        configure = [
            "cmake", "-S", str(ROOT / "python"), "-B", str(build_dir),
            "-DCMAKE_BUILD_TYPE=Release",
            f"-DPython3_EXECUTABLE={sys.executable}",
            f"-DFACET_PYTHON_VERSION={version()}",
        ]
        prefix = os.environ.get("FACET_PREFIX")
        if prefix:
            prefixes = [prefix] + os.environ.get("CMAKE_PREFIX_PATH", "").split(os.pathsep)
            configure.append("-DCMAKE_PREFIX_PATH=" + ";".join(p for p in prefixes if p))
        subprocess.run(configure, check=True)
        jobs = os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL", str(os.cpu_count() or 1))
        subprocess.run(["cmake", "--build", str(build_dir), "--target", "facet_python",
                        "--parallel", jobs], check=True)
        built = list((build_dir / "package" / "facet").glob("_facet*.so"))
        if len(built) != 1:
            sys.exit(f"setup.py: expected one _facet*.so in {build_dir}/package/facet, got {built}")
        target = pathlib.Path(self.get_ext_fullpath(extension.name))
        target.parent.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(built[0], target)


setup(
    name="facet",
    version=version(),
    description="A CPU software rasterizer: NumPy images, depth and cameras without a GPU",
    license="MIT",
    python_requires=">=3.9",
    install_requires=["numpy"],
    extras_require={"dask": ["distributed"]},  # facet.dask.render; pip install ".[dask]"
    packages=["facet"],
    package_dir={"": "python"},
    ext_modules=[CMakeExtension()],
    cmdclass={"build_ext": BuildWithCMake},
    options={"build": {"build_base": str(BUILD_BASE)}, "egg_info": {"egg_base": str(BUILD_BASE)}},
    zip_safe=False,
)
