"""The module gives the program's values to the last bit: its write_ply
writes the bytes of the program's curvatures.ply, on the bundled bunny,
libcgal-demo's kitten.xyz and building.ply with and without their normals,
and a 100k noisy ellipsoid; on the bunny the CSV's doubles equal the arrays."""
import os
import subprocess

import numpy as np
import pytest

import conformal_alpha_shapes as cas
from conftest import ellipsoid, required_path, scan_path


def program_output(input_path, folder, *options):
    program = required_path("CAS3_PROGRAM", "the conformal_curvature program")
    subprocess.run([program, str(input_path), "--quiet", "--output", str(folder), *options], check=True)
    return folder


def check_same_bytes(tmp_path, input_path, points, normals):
    expected = program_output(input_path, tmp_path / "program") / "curvatures.ply"
    r = cas.multiscale_curvatures(points, normals)
    r.write_ply(tmp_path / "module.ply")
    assert (tmp_path / "module.ply").read_bytes() == expected.read_bytes()
    return r


def test_bunny_ply_and_csv(tmp_path):
    bunny = required_path("CAS3_BUNNY_XYZ", "the bundled bunny")
    points, normals = cas.read_point_cloud(bunny)
    assert normals is None
    r = check_same_bytes(tmp_path, bunny, points, None)
    # the program's file read back: its floats, which write the same bytes
    read = cas.read_curvatures(tmp_path / "program" / "curvatures.ply")
    assert read.layers == r.layers and np.array_equal(read.points, points)
    assert np.array_equal(read["r4s"].H, r["r4s"].H.astype(np.float32).astype(np.float64), equal_nan=True)
    (tmp_path / "again").mkdir()
    read.write_ply(tmp_path / "again" / "curvatures.ply")
    assert (tmp_path / "again" / "curvatures.ply").read_bytes() == \
        (tmp_path / "program" / "curvatures.ply").read_bytes()
    program_output(bunny, tmp_path / "csv", "--csv")
    table = np.genfromtxt(tmp_path / "csv" / "curvatures.csv", delimiter=",", names=True, dtype=None,
                          encoding="ascii")
    for k, name in enumerate(r.layers):
        rows = table[k * len(points):(k + 1) * len(points)]
        assert (rows["neighborhood"] == name).all()
        layer = r[name]
        for column, values in (("H", layer.H), ("K", layer.K), ("k1", layer.k1), ("k2", layer.k2),
                               ("nx", layer.normal[:, 0]), ("d2z", layer.d2[:, 2]),
                               ("radius", layer.radius), ("distance", layer.distance)):
            assert np.array_equal(rows[column], values, equal_nan=True), (name, column)
        assert np.array_equal(rows["source"], layer.source)
        assert (rows["a"] == layer.a).all()


@pytest.mark.parametrize("name", ["kitten.xyz", "building.ply"])
@pytest.mark.parametrize("with_normals", [True, False], ids=["normals", "points only"])
def test_scans(tmp_path, name, with_normals):
    points, normals = cas.read_point_cloud(scan_path(name))
    assert normals is not None
    path = scan_path(name)
    if not with_normals:
        path = tmp_path / "points.xyz"
        np.savetxt(path, points, fmt="%.17g")
        normals = None
    check_same_bytes(tmp_path, path, points, normals)


def test_noisy_ellipsoid_100k(tmp_path):
    points, _, _ = ellipsoid(100000, (1.5, 1.0, 0.75), noise=0.003, seed=7)
    path = tmp_path / "ellipsoid.xyz"
    np.savetxt(path, points, fmt="%.17g")
    r = check_same_bytes(tmp_path, path, np.loadtxt(path), None)
    assert r.denoised
