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
    r.write_ply(tmp_path / "module.ply", precision="float32")
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
    read.write_ply(tmp_path / "again" / "curvatures.ply", precision="float32")
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


def test_uncertainty_summary_is_the_programs(tmp_path):
    """The bunny's layers, some noise-dominated and some bias-dominated: the
    program's summary line and ``Result.uncertainty_summary()`` say the same."""
    bunny = required_path("CAS3_BUNNY_XYZ", "the bundled bunny")
    run = subprocess.run([required_path("CAS3_PROGRAM", "the conformal_curvature program"), str(bunny), "--output",
                          str(tmp_path / "out")], check=True, capture_output=True, text=True)
    line = next(line for line in run.stdout.splitlines() if line.startswith("uncertainty of H"))
    r = cas.multiscale_curvatures(*cas.read_point_cloud(bunny))
    words = {None: "", "noise": " noise-dominated", "bias": " bias-dominated"}
    items = [f"{name} {100 * relative:.3g}%{words[dominated]}"
             for name, (relative, _, dominated) in r.uncertainty_summary().items()]
    assert line.split(": ", 1)[1] == ", ".join(items)
    assert {dominated for _, _, dominated in r.uncertainty_summary().values()} == {"noise", "bias"}
    for name in r.layers:
        sigma, noise = r[name].H_sigma, r[name].H_noise_sigma
        assert np.all(noise[np.isfinite(sigma)] <= sigma[np.isfinite(sigma)] * (1 + 1e-12))


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


def test_las_the_program_and_the_module_write_the_same_bytes(tmp_path):
    """A LAS 1.3 file (point format 3, an extra-bytes field, a GeoTIFF CRS)
    of the kitten with noise of class 7: the program's --classes 2 --las and the module's read_point_cloud and
    write_las give the same curvatures.las; so do both on the .xyz of the
    kitten (a chosen scale)."""
    import las_spec
    points, _ = cas.read_point_cloud(scan_path("kitten.xyz"))
    rng = np.random.default_rng(2)
    everything = np.vstack([points, rng.uniform(points.min(axis=0), points.max(axis=0), (500, 3))])
    order = rng.permutation(len(everything))
    fields = las_spec.sample_fields(len(everything), 3)
    for k, axis in enumerate("XYZ"):
        fields[axis] = np.round(everything[order, k] / 1e-6).astype(np.int32)
    fields["classification"] = np.where(order < len(points), 2, 7).astype(np.uint8)
    path = tmp_path / "kitten.las"
    las_spec.write_las(path, 3, 3, fields, scale=(1e-6,) * 3, offset=(0.0,) * 3, crs="geotiff",
                       extra=[("reflectance", "<f4", np.linspace(0, 1, len(everything)).astype(np.float32))])
    expected = program_output(path, tmp_path / "program", "--las", "--classes", "2") / "curvatures.las"
    cloud = cas.read_point_cloud(path, classes=[2])
    assert len(cloud.points) == len(points)
    cas.multiscale_curvatures(cloud.points).write_las(tmp_path / "module.las", cloud)
    assert (tmp_path / "module.las").read_bytes() == expected.read_bytes()
    header, _, extra, _ = las_spec.read_las(expected)
    assert header["descriptors"][0]["name"] == "reflectance" and len(las_spec.crs_records(header)) == 3

    xyz = tmp_path / "kitten_points.xyz"
    np.savetxt(xyz, points, fmt="%.17g")
    expected = program_output(xyz, tmp_path / "program_xyz", "--las") / "curvatures.las"
    cas.multiscale_curvatures(points).write_las(tmp_path / "module_xyz.las")
    assert (tmp_path / "module_xyz.las").read_bytes() == expected.read_bytes()
