"""The Python example runs, and the module works from an install prefix."""
import os
import subprocess
import sys

from conftest import required_path


def run_python(code_or_script, pythonpath, *args, cwd=None):
    env = dict(os.environ, PYTHONPATH=pythonpath)
    command = [sys.executable] + ([code_or_script] if code_or_script.endswith(".py") else ["-c", code_or_script])
    command += list(args)
    return subprocess.run(command, env=env, cwd=cwd, check=True, capture_output=True, text=True).stdout


def test_example_writes_the_ply_and_the_picture(tmp_path):
    source = required_path("CAS3_SOURCE_DIR", "the source folder")
    script = os.path.join(source, "examples", "Conformal_alpha_shapes_3", "python", "curvature_of_a_scan.py")
    out = run_python(script, os.environ["PYTHONPATH"], cwd=str(tmp_path))  # the bundled bunny
    assert "5000 points" in out and "layers rauto, r2s, r4s, r8s, r16s" in out and "100%" in out
    folder = tmp_path / "curvature_of_a_scan_out"
    assert (folder / "curvatures.ply").stat().st_size > 5000 * 8
    # Debian's python3-matplotlib is installed by the README's first command
    assert (folder / "mean_curvature_r4s.png").read_bytes()[:4] == b"\x89PNG", out


def test_module_from_an_install_prefix(tmp_path):
    build = required_path("CAS3_BUILD_DIR", "the build folder")
    subprocess.run(["cmake", "--install", build, "--prefix", str(tmp_path)], check=True, capture_output=True)
    site = tmp_path / "lib" / f"python{sys.version_info[0]}.{sys.version_info[1]}" / "site-packages"
    assert (site / "conformal_alpha_shapes" / "__init__.pyi").exists()
    out = run_python("import numpy as np, conformal_alpha_shapes as cas\n"
                     "print(cas.__file__)\n"
                     "p = np.random.default_rng(1).normal(size=(2000, 3))\n"
                     "p /= np.linalg.norm(p, axis=1)[:, None]\n"
                     "print(round(float(np.median(cas.multiscale_curvatures(p, radii=['4s'])['r4s'].H)), 2))",
                     str(site), cwd=str(tmp_path))
    assert out.splitlines() == [str(site / "conformal_alpha_shapes" / "__init__.py"), "1.0"]
