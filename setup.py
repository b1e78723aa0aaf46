"""The wheel's build step: the project's own CMake build of the extension, the library and the
`raylab` command, laid out inside the package (pyproject.toml holds the metadata).

The package in the wheel:
    raylab/__init__.py, __init__.pyi, py.typed, _command.py   the Python side (python/raylab)
    raylab/_build.py                                           how it was built (CMake writes it)
    raylab/_raylab.<abi>.so                                    the extension, run path $ORIGIN/lib
    raylab/lib/libraylab.so.0, libraylab_dist.so.0             the libraries, by their sonames
    raylab/lib/libraylab_exr.so, libraylab_embree.so           the modules libraylab loads
    raylab/bin/raylab                                          the command, run path $ORIGIN/../lib
A wheel holds no symbolic links, so each library is shipped once, under the name the loader
looks for. The C++ dependencies (TBB, OpenEXR, fmt, Embree) are the system's shared libraries.

Environment: RAYLAB_CMAKE_ARGS adds configure options (e.g. -DRAYLAB_WERROR=ON);
RAYLAB_WHEEL_BUILD_DIR moves the CMake build folder (default build/wheel, kept between builds
so that a second `pip install .` rebuilds only what changed); CMAKE_BUILD_PARALLEL_LEVEL sets
the number of compile jobs.
"""

import os
import pathlib
import re
import shlex
import shutil
import subprocess
import sys

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

SOURCE_DIR = pathlib.Path(__file__).resolve().parent


def project_version():
    """CMake's project version (CMakeLists.txt), the one source of the version."""
    text = (SOURCE_DIR / "CMakeLists.txt").read_text(encoding="utf-8")
    match = re.search(r"^project\(raylab VERSION ([0-9.]+)", text, re.MULTILINE)
    if not match:
        raise RuntimeError("CMakeLists.txt: no 'project(raylab VERSION x.y.z' line")
    return match.group(1)


def pybind11_cmake_dir():
    """The CMake folder of the pybind11 this interpreter imports (the build requirement), if any."""
    try:
        import pybind11
    except ImportError:
        return None
    return pybind11.get_cmake_dir()


# What CMakeBuild lays beside the extension: its path in the package, from its path in the CMake
# build folder (the libraries by their soname links, which the copy follows to the files).
BESIDE_EXTENSION = {
    "_build.py": "python/raylab/_build.py",
    "lib/libraylab.so.0": "lib/libraylab.so.0",
    "lib/libraylab_dist.so.0": "lib/libraylab_dist.so.0",
    "lib/libraylab_exr.so": "lib/libraylab_exr.so",
    "lib/libraylab_embree.so": "lib/libraylab_embree.so",
    "bin/raylab": "bin/raylab",
}


class CMakeBuild(build_ext):
    """Builds the extension with CMake and puts the library and the command beside it."""

    def beside_extension(self):
        """(built, in the source tree) pairs of the files laid beside the extension, for an
        editable install (`pip install -e .`), which copies the extension back into python/raylab."""
        built = pathlib.Path(self.build_lib) / "raylab"
        in_source = pathlib.Path(self.get_finalized_command("build_py").get_package_dir("raylab"))
        return [(str(built / name), str(in_source / name)) for name in BESIDE_EXTENSION]

    def copy_extensions_to_source(self):
        super().copy_extensions_to_source()
        for built, in_source in self.beside_extension():
            pathlib.Path(in_source).parent.mkdir(parents=True, exist_ok=True)
            shutil.copy2(built, in_source)

    def get_output_mapping(self):
        mapping = super().get_output_mapping()
        if self.inplace:
            mapping.update(self.beside_extension())
        return mapping

    def build_extension(self, ext):
        build_dir = pathlib.Path(os.environ.get("RAYLAB_WHEEL_BUILD_DIR", SOURCE_DIR / "build" / "wheel"))
        configure = [
            "cmake", "-S", str(SOURCE_DIR), "--preset", "release", "-B", str(build_dir),
            "-DRAYLAB_BUILD_TESTS=OFF", "-DRAYLAB_BUILD_BENCH=OFF", "-DRAYLAB_BUILD_FUZZ=OFF",
            # The command in the wheel renders on one machine; distributed rendering would tie
            # the wheel to the build machine's MPI.
            "-DRAYLAB_WITH_MPI=OFF",
            f"-DRAYLAB_PYTHON={sys.executable}",
            # Built with the run paths of the package's layout (the docstring above), so that
            # the files are copied as they are, with no path of this machine inside.
            "-DCMAKE_BUILD_WITH_INSTALL_RPATH=ON",
            "-DCMAKE_INSTALL_LIBDIR=lib",
            "-DRAYLAB_PYTHON_MODULE_RPATH=$ORIGIN/lib",
        ]
        cmake_dir = pybind11_cmake_dir()
        if cmake_dir:
            configure.append(f"-Dpybind11_DIR={cmake_dir}")
        configure += shlex.split(os.environ.get("RAYLAB_CMAKE_ARGS", ""))
        jobs = os.environ.get("CMAKE_BUILD_PARALLEL_LEVEL", str(os.cpu_count() or 1))
        self.spawn(configure)
        self.spawn(["cmake", "--build", str(build_dir), "--target", "raylab_python", "raylab_cli", "-j", jobs])

        extension = pathlib.Path(self.get_ext_fullpath(ext.name))
        package = extension.parent
        built = sorted((build_dir / "python" / "raylab").glob("_raylab*.so"))
        if len(built) != 1:
            raise RuntimeError(f"expected one extension module in {build_dir}/python/raylab, found {built}")
        package.mkdir(parents=True, exist_ok=True)
        shutil.copyfile(built[0], extension)
        for name, in_build in BESIDE_EXTENSION.items():
            (package / name).parent.mkdir(parents=True, exist_ok=True)
            shutil.copy2(build_dir / in_build, package / name)  # keeps the command executable


setup(
    version=project_version(),
    # One extension, named so that setuptools makes a platform wheel and knows where it goes;
    # CMake compiles it (CMakeBuild), setuptools compiles nothing.
    ext_modules=[Extension("raylab._raylab", sources=[])],
    cmdclass={"build_ext": CMakeBuild},
)
