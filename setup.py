"""The wheel of the Python module ``conformal_alpha_shapes``: its Python files
(``python/conformal_alpha_shapes``) and its compiled half ``_native``, built
by the project's CMake (pyproject.toml; the manual, "Python").

The compiled half comes from a CMake build folder, the first of:
- the folder in the environment variable CAS3_CMAKE_BUILD_DIR (configured
  with the Python module; ``cmake --build`` brings ``_native`` up to date);
- ``build/`` beside this file when it is a CMake build of this source tree
  whose module was built for this interpreter (the README's first command
  makes it);
- a new Release build (no tests) in setuptools' temporary folder, for this
  interpreter: the one translation unit of the module, a few minutes.
Nothing is downloaded.
"""
import os
import re
import shutil
import subprocess
import sys
import sysconfig

from setuptools import Extension, setup
from setuptools.command.build_ext import build_ext

HERE = os.path.dirname(os.path.abspath(__file__))


def cmake_project_version():
    """The version in CMakeLists.txt's project(... VERSION x.y.z): the package's only copy."""
    with open(os.path.join(HERE, "CMakeLists.txt")) as f:
        match = re.search(r"project\(\s*Conformal_alpha_shapes_3\s+VERSION\s+([0-9][0-9.]*)", f.read())
    if not match:
        raise RuntimeError("CMakeLists.txt has no project(Conformal_alpha_shapes_3 VERSION x.y.z)")
    return match.group(1)


def cache_entry(build_dir, name):
    """An entry of a CMake build folder's CMakeCache.txt, or None."""
    try:
        with open(os.path.join(build_dir, "CMakeCache.txt")) as f:
            for line in f:
                if line.startswith(name + ":"):
                    return line.split("=", 1)[1].strip()
    except OSError:
        pass
    return None


class CMakeBuild(build_ext):
    """Builds the CMake target ``_native`` and copies it into the wheel."""

    def run(self):
        if shutil.which("cmake") is None:
            raise RuntimeError("building conformal_alpha_shapes needs CMake: apt-get install cmake")
        super().run()

    def build_extension(self, ext):
        suffix = sysconfig.get_config_var("EXT_SUFFIX")
        given = os.environ.get("CAS3_CMAKE_BUILD_DIR")
        if given:
            if cache_entry(given, "CMAKE_HOME_DIRECTORY") is None:
                raise RuntimeError(f"CAS3_CMAKE_BUILD_DIR={given} is not a CMake build folder (no CMakeCache.txt)")
            built = self.build_target(given, suffix)
            if built is None:
                raise RuntimeError(f"CAS3_CMAKE_BUILD_DIR={given}: its Python module is not built for this "
                                   f"interpreter ({sys.executable}, {suffix}); configure it with "
                                   f"-DPython3_EXECUTABLE={sys.executable}")
        else:
            built = None
            beside = os.path.join(HERE, "build")
            if self.is_build_of_this_tree(beside):
                built = self.build_target(beside, suffix)
            if built is None:
                built = self.build_target(self.configure_new_build(), suffix)
            if built is None:
                raise RuntimeError("the CMake build did not make the Python module: it needs python3-dev, "
                                   "python3-numpy and pybind11-dev (Debian), and libcgal-dev, libeigen3-dev")
        target = self.get_ext_fullpath(ext.name)
        os.makedirs(os.path.dirname(target), exist_ok=True)
        shutil.copyfile(built, target)

    @staticmethod
    def is_build_of_this_tree(build_dir):
        """Whether ``build_dir`` is a CMake build of this source tree with the module, for this
        interpreter (the same executable, or a module of its suffix already built)."""
        home = cache_entry(build_dir, "CMAKE_HOME_DIRECTORY")
        if home is None or os.path.realpath(home) != os.path.realpath(HERE):
            return False
        interpreter = cache_entry(build_dir, "Python3_EXECUTABLE")
        built = os.path.join(build_dir, "python", "conformal_alpha_shapes",
                             "_native" + sysconfig.get_config_var("EXT_SUFFIX"))
        return (interpreter is not None and os.path.realpath(interpreter) == os.path.realpath(sys.executable)
                or os.path.exists(built))

    def build_target(self, build_dir, suffix):
        """Builds ``_native`` in ``build_dir``; its path, or None when that build does not make
        one for this interpreter."""
        if not os.path.isdir(os.path.join(build_dir, "python", "CMakeFiles", "_native.dir")):
            return None
        command = ["cmake", "--build", build_dir, "--target", "_native"]
        if "CMAKE_BUILD_PARALLEL_LEVEL" not in os.environ:
            command += ["-j", str(os.cpu_count() or 1)]
        subprocess.run(command, check=True)
        built = os.path.join(build_dir, "python", "conformal_alpha_shapes", "_native" + suffix)
        return built if os.path.exists(built) else None

    def configure_new_build(self):
        build_dir = os.path.join(os.path.abspath(self.build_temp), "cmake")
        os.makedirs(build_dir, exist_ok=True)
        subprocess.run(["cmake", "-S", HERE, "-B", build_dir, "-DCMAKE_BUILD_TYPE=Release", "-DBUILD_TESTING=OFF",
                        "-DCAS3_PRECOMPILED_HEADERS=OFF", f"-DPython3_EXECUTABLE={sys.executable}"], check=True)
        return build_dir


setup(
    version=cmake_project_version(),
    package_dir={"": "python"},
    packages=["conformal_alpha_shapes"],
    package_data={"conformal_alpha_shapes": ["*.pyi", "py.typed"]},
    ext_modules=[Extension("conformal_alpha_shapes._native", sources=[])],
    cmdclass={"build_ext": CMakeBuild},
    zip_safe=False,
)
