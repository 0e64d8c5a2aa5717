"""The module installed as Python users install it, offline: pip into a
virtual environment (--no-build-isolation), a wheel and a source
distribution with python3 -m build --no-isolation, cmake --install for
/usr/local, /usr and a prefix of one's own; the version in one place.

The builds reuse the CMake build folder of the tests (CAS3_CMAKE_BUILD_DIR,
setup.py), so that the file takes about half a minute; setup.py's own build
in a fresh clone (no build folder) is the same CMake build of one target."""
import os
import re
import shutil
import subprocess
import sys
import sysconfig
import tarfile
import zipfile

import pytest

from conftest import required_path

VERSION_SCRIPT = ("import importlib.metadata, conformal_alpha_shapes as c\n"
                  "print(c.__version__, importlib.metadata.version('conformal_alpha_shapes'), c.__file__)")


def project_version():
    source = required_path("CAS3_SOURCE_DIR", "the source folder")
    with open(os.path.join(source, "CMakeLists.txt")) as f:
        return re.search(r"project\(Conformal_alpha_shapes_3 VERSION ([0-9.]+)", f.read()).group(1)


def clean_environment(**extra):
    """The environment without the build tree on PYTHONPATH (as a user's shell), offline for pip."""
    env = {k: v for k, v in os.environ.items() if k not in ("PYTHONPATH", "PYTHONHOME")}
    env.update(PIP_NO_INDEX="1", PIP_DISABLE_PIP_VERSION_CHECK="1", PIP_NO_INPUT="1", **extra)
    return env


def require_module(name, package):
    import importlib.util
    if importlib.util.find_spec(name) is None:
        pytest.fail(f"{sys.executable} has no module {name}: apt-get install {package}")


def run(command, **kwargs):
    done = subprocess.run(command, capture_output=True, text=True, **kwargs)
    assert done.returncode == 0, f"{command} failed:\n{done.stdout}\n{done.stderr}"
    return done.stdout


@pytest.fixture(scope="module")
def source_copy(tmp_path_factory):
    """The source tree as a fresh clone has it (no build folders), in a temporary folder."""
    source = required_path("CAS3_SOURCE_DIR", "the source folder")
    copy = tmp_path_factory.mktemp("clone") / "Conformal_alpha_shapes_3"
    shutil.copytree(source, copy, ignore=shutil.ignore_patterns(
        ".git", "build", "build-*", "dist", "__pycache__", "*.egg-info", "conformal_curvature_out"))
    return copy


def reuse_build():
    return {"CAS3_CMAKE_BUILD_DIR": required_path("CAS3_BUILD_DIR", "the build folder")}


def test_pip_install_into_a_virtual_environment(source_copy, tmp_path):
    require_module("ensurepip", "python3-venv")
    require_module("setuptools", "python3-setuptools")
    require_module("wheel", "python3-wheel")
    venv = tmp_path / "venv"
    run([sys.executable, "-m", "venv", "--system-site-packages", str(venv)])
    pip = [str(venv / "bin" / "python"), "-m", "pip"]
    run(pip + ["install", "--no-build-isolation", str(source_copy)], env=clean_environment(**reuse_build()))
    elsewhere = tmp_path / "elsewhere"
    elsewhere.mkdir()
    version, metadata, where = run([str(venv / "bin" / "python"), "-c", VERSION_SCRIPT], cwd=elsewhere,
                                   env=clean_environment()).split()
    assert version == metadata == project_version()
    assert where.startswith(str(venv)) and where.endswith(os.path.join("conformal_alpha_shapes", "__init__.py"))
    package = os.path.dirname(where)
    assert os.path.exists(os.path.join(package, "__init__.pyi")) and os.path.exists(os.path.join(package, "py.typed"))
    # the installed module computes
    out = run([str(venv / "bin" / "python"), "-c",
               "import numpy as np, conformal_alpha_shapes as c\n"
               "p = np.random.default_rng(1).normal(size=(2000, 3))\n"
               "p /= np.linalg.norm(p, axis=1)[:, None]\n"
               "print(round(float(np.median(c.multiscale_curvatures(p, radii=['4s'])['r4s'].H)), 2))"],
              cwd=elsewhere, env=clean_environment())
    assert out.strip() == "1.0"
    run(pip + ["uninstall", "-y", "conformal_alpha_shapes"], env=clean_environment())
    assert not os.path.exists(package)


def test_build_makes_a_wheel_and_a_source_distribution(source_copy, tmp_path):
    require_module("build", "python3-build")
    dist = tmp_path / "dist"
    run([sys.executable, "-m", "build", "--no-isolation", "--outdir", str(dist), str(source_copy)],
        env=clean_environment(**reuse_build()))
    version = project_version()
    wheels = list(dist.glob(f"conformal_alpha_shapes-{version}-*.whl"))
    sdists = list(dist.glob(f"conformal_alpha_shapes-{version}.tar.gz"))
    assert len(wheels) == 1 and len(sdists) == 1, os.listdir(dist)
    with zipfile.ZipFile(wheels[0]) as wheel:
        names = wheel.namelist()
        metadata = wheel.read(f"conformal_alpha_shapes-{version}.dist-info/METADATA").decode()
    suffix = sysconfig.get_config_var("EXT_SUFFIX")
    for name in ("__init__.py", "__init__.pyi", "py.typed", "tiles.py", "curvature_file.py", "_native" + suffix):
        assert f"conformal_alpha_shapes/{name}" in names, name
    assert f"Version: {version}" in metadata and "Requires-Dist: numpy" in metadata
    # the source distribution is the whole CMake project, which setup.py builds
    with tarfile.open(sdists[0]) as sdist:
        members = {name.split("/", 1)[1] for name in sdist.getnames() if "/" in name}
    for name in ("CMakeLists.txt", "setup.py", "pyproject.toml", "include/CGAL/Conformal_alpha_shape_3.h",
                 "python/conformal_alpha_shapes_native.cpp", "python/CMakeLists.txt",
                 "examples/Conformal_alpha_shapes_3/CMakeLists.txt",
                 "examples/Conformal_alpha_shapes_3/data/bunny_5000.xyz",
                 "doc/Conformal_alpha_shapes_3/Doxyfile.in", "test/Conformal_alpha_shapes_3/CMakeLists.txt",
                 "benchmark/Conformal_alpha_shapes_3/CMakeLists.txt"):
        assert name in members, name


def install(prefix, destdir=None):
    build = required_path("CAS3_BUILD_DIR", "the build folder")
    env = dict(os.environ, DESTDIR=str(destdir)) if destdir else None
    run(["cmake", "--install", build, "--prefix", str(prefix)], env=env)


@pytest.mark.parametrize("prefix", ["/usr/local", "/usr"])
def test_cmake_install_for_the_system_prefixes(tmp_path, prefix):
    """Staged with DESTDIR: the folder is one Debian's /usr/bin/python3 searches."""
    install(prefix, destdir=tmp_path)
    site = f"{prefix}/lib/python{sys.version_info[0]}.{sys.version_info[1]}/dist-packages"
    assert (tmp_path / site.lstrip("/") / "conformal_alpha_shapes" / "__init__.py").exists()
    if os.path.exists("/etc/debian_version") and sys.executable.startswith("/usr/bin/"):
        searched = run([sys.executable, "-c", "import sys; print('\\n'.join(sys.path))"],
                       env=clean_environment()).split()
        assert site in searched, searched
    staged = str(tmp_path / site.lstrip("/"))
    version, metadata, where = run([sys.executable, "-c", VERSION_SCRIPT], cwd=tmp_path,
                                   env=clean_environment(PYTHONPATH=staged)).split()
    assert version == metadata == project_version() and where.startswith(staged)


def test_cmake_install_into_a_virtual_environment(tmp_path):
    """Another prefix gets lib/python3.X/site-packages: a virtual environment's there imports it."""
    venv = tmp_path / "venv"
    run([sys.executable, "-m", "venv", "--system-site-packages", "--without-pip", str(venv)])
    install(venv)
    elsewhere = tmp_path / "elsewhere"
    elsewhere.mkdir()
    version, metadata, where = run([str(venv / "bin" / "python"), "-c", VERSION_SCRIPT], cwd=elsewhere,
                                   env=clean_environment()).split()
    assert version == metadata == project_version() and where.startswith(str(venv / "lib"))
