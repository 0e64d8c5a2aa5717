"""The module's functions on shapes with known values: a sphere, ellipsoids
(clean and noisy), a mesh of a sphere; the result's layers, arrays and
conversions."""
import numpy as np
import pytest

import conformal_alpha_shapes as cas
from conftest import ellipsoid, fibonacci_sphere, scan_path


@pytest.fixture(scope="module")
def sphere_result():
    points, normals = fibonacci_sphere(4000, radius=2.0)
    return points, normals, cas.multiscale_curvatures(points)


def test_sphere_layers_and_values(sphere_result):
    points, normals, r = sphere_result
    assert r.layers == ("rauto", "r2s", "r4s", "r8s", "r16s")
    assert r.outlier.shape == (4000,) and not r.outlier.any()
    assert not r.denoised and r.noise < 0.02
    # 16 spacings are the sphere's radius: that fit spans a hemisphere
    bound = {"rauto": 1e-3, "r2s": 1e-3, "r4s": 1e-3, "r8s": 5e-3, "r16s": 0.06}
    for name in r.layers:
        layer = r[name]
        assert layer.name == name and layer.a > 0
        assert (layer.source == 0).all()
        assert np.abs(layer.H - 0.5).max() < bound[name], name
        assert np.abs(layer.K - 0.25).max() < bound[name], name
        assert np.abs(np.einsum("ij,ij->i", layer.normal, normals) - 1).max() < (1e-3 if name != "r16s" else 5e-3), name
        assert (layer.k1 >= layer.k2).all()
        for key, shape in (("d1", (4000, 3)), ("d2", (4000, 3)), ("radius", (4000,)), ("distance", (4000,))):
            assert layer[key].shape == shape and layer[key].dtype == np.float64
        assert layer.source.dtype == np.uint8
    with pytest.raises(KeyError, match="rauto"):
        r["r3s"]


def test_noisy_ellipsoid_outward_and_accurate():
    points, normals, H = ellipsoid(20000, (1.5, 1.0, 0.75), noise=0.002)
    r = cas.multiscale_curvatures(points, radii=("auto", "4s"))
    assert r.denoised
    for name in r.layers:
        assert (np.einsum("ij,ij->i", r[name].normal, normals) > 0.9).all(), name
    # the automatic radius (measured: median 1.4%, 99th percentile 4.5%); a
    # fixed 4 spacings follows the noise left after smoothing (median 7.5%)
    relative = np.abs(r["rauto"].H - H) / np.abs(H)
    assert np.median(relative) < 0.02 and np.percentile(relative, 99) < 0.06


def test_spacing_and_noise_of_a_larger_run():
    # noisy, so that the given noise decides the denoising too
    points, _, _ = ellipsoid(5000, (1.5, 1.0, 0.75), noise=0.002)
    own = cas.multiscale_curvatures(points)
    assert own.denoised
    given = cas.multiscale_curvatures(points, spacing=own.spacing, noise=own.noise)
    assert given.spacing == own.spacing and given.noise == own.noise and given.denoised
    for name in own.layers:
        for key in ("H", "K", "k1", "k2", "normal", "d1", "d2", "radius", "distance", "source"):
            assert own[name][key].tobytes() == given[name][key].tobytes(), (name, key)
    coarser = cas.multiscale_curvatures(points, radii=("4s",), spacing=2 * own.spacing, noise=own.noise)
    on_surface = coarser["r4s"].source == 0
    assert on_surface.any()
    assert (coarser["r4s"].radius[on_surface] == 2 * own["r4s"].radius[on_surface]).all()
    assert not cas.multiscale_curvatures(points, radii=("4s",), spacing=own.spacing, noise=0.0).denoised


def test_a_larger_runs_noise_carries_its_denoising_decision():
    """An airborne scan whose noise (0.065 spacings) reads half as large
    again with 24 neighbors (detail the sampling does not resolve): not
    smoothed. Its own ``r.noise`` given back carries that reading, so the
    same decision and the same values to the bit (with the noise alone the
    run was smoothed and its scale 20% off); a plain float reads the noise
    alone, as documented."""
    points, _ = cas.read_point_cloud(scan_path("b9_training.ply"))
    own = cas.multiscale_curvatures(points, radii=("4s",))
    assert not own.denoised and own.noise > 0.02 and own.noise.noise_24 > 1.3 * own.noise
    assert not own.noise.calls_for_denoising
    given = cas.multiscale_curvatures(points, radii=("4s",), spacing=own.spacing, noise=own.noise)
    assert not given.denoised and given["r4s"].a == own["r4s"].a
    for key in ("H", "K", "normal", "radius", "source"):
        assert own["r4s"][key].tobytes() == given["r4s"][key].tobytes(), key
    assert cas.multiscale_curvatures(points, radii=("4s",), spacing=own.spacing, noise=float(own.noise)).denoised


def test_front_closing_values_give_the_automatic_scale():
    """The mean of their ranks 0.99 n to 0.999 n is the automatic scale (tiled runs pool them over tiles)."""
    points, _ = fibonacci_sphere(3000)
    points = np.vstack([points, points[:5]])  # coincident points count once
    closing = cas.front_closing_values(points)
    assert closing.shape == (3005,) and np.isnan(closing[3000:]).all()
    values = np.sort(closing[~np.isnan(closing)])
    window = values[int(0.99 * len(values)):int(0.999 * len(values))]
    a = cas.multiscale_curvatures(points, radii=("4s",))["r4s"].a
    assert float(np.cumsum(window)[-1] / len(window)) == a
    # the shape of the points as given (not recentered): the same to rounding
    assert a == pytest.approx(cas.ConformalAlphaShape(points[:3000]).suggest_scale(), rel=1e-12)


def test_given_inward_normals_are_followed():
    points, normals, H = ellipsoid(5000, (1.5, 1.0, 0.75))
    r = cas.multiscale_curvatures(points, -normals, radii=("4s",))
    layer = r["r4s"]
    assert (np.einsum("ij,ij->i", layer.normal, normals) < -0.9).all()
    assert (layer.H < 0).all()


def test_structured_array(sphere_result):
    points, _, r = sphere_result
    s = r.to_structured("r4s")
    assert s.shape == (4000,)
    assert np.array_equal(s["X"], points[:, 0]) and np.array_equal(s["NormalZ"], r["r4s"].normal[:, 2])
    assert np.array_equal(s["H"], r["r4s"].H) and np.array_equal(s["d2y"], r["r4s"].d2[:, 1])
    assert s["source"].dtype == np.uint8 and s["outlier"].dtype == np.bool_


def test_several_scales_and_rings():
    points, _ = fibonacci_sphere(3000)
    r = cas.multiscale_curvatures(points, scales=("auto", "50%"), radii=(), rings=(2,))
    assert r.layers == ("auto_k2", "50pct_k2")
    assert r["auto_k2"].a != r["50pct_k2"].a
    assert np.abs(r["auto_k2"].H - 1).max() < 0.02


def test_conformal_alpha_shape():
    points, normals, _ = ellipsoid(2000, (1.2, 1.0, 0.8))
    shape = cas.ConformalAlphaShape(points)
    spectrum = shape.spectrum()
    assert spectrum.ndim == 1 and (np.diff(spectrum) > 0).all()
    a = shape.suggest_scale()
    assert shape.alpha_at_quantile(0) <= shape.alpha_at_quantile(0.5) <= shape.alpha_at_quantile(1)
    counts = shape.classify_facets(a)
    assert set(counts) == {"exterior", "singular", "regular", "interior"}
    assert sum(counts.values()) > 3 * 2000 and counts["regular"] + counts["singular"] > 0
    vertices, faces, index = shape.surface()
    assert vertices.dtype == np.float64 and faces.dtype == np.int64 and index.dtype == np.int64
    # at the automatic scale 99% of the umbrellas are whole: a few small holes
    # (a vertex where two fans of faces meet is written once per fan)
    assert np.array_equal(np.unique(index), np.arange(2000)) and 0.99 * (2 * 2000 - 4) <= len(faces) < 2 * 2000 - 4
    assert np.array_equal(vertices, points[index])
    vertices, faces, index = shape.surface(1.5 * a)
    assert len(faces) == 2 * 2000 - 4  # closed: V - E + F = 2
    # outward: each face's normal along its centroid
    p = vertices[faces]
    face_normals = np.cross(p[:, 1] - p[:, 0], p[:, 2] - p[:, 0])
    assert (np.einsum("ij,ij->i", face_normals, p.mean(axis=1)) > 0).all()
    solid = shape.surface(shape.suggest_scale(extraction="solid"), extraction="solid")
    assert len(solid[1]) == 2 * 2000 - 4


def test_local_scales_change_the_filtration():
    points, _ = fibonacci_sphere(500)
    default = cas.ConformalAlphaShape(points).spectrum()
    unit = cas.ConformalAlphaShape(points, local_scales=np.ones(500)).spectrum()
    halved = cas.ConformalAlphaShape(points, local_scales=np.full(500, 0.5)).spectrum()
    assert not np.array_equal(default, unit)
    # a uniform local scale divides every value by the same factor
    finite = np.isfinite(unit) & (unit > 0)
    ratio = halved[finite] / unit[finite]
    assert np.allclose(ratio, ratio[0], rtol=1e-9) and ratio[0] > 1


def icosphere(subdivisions):
    t = (1 + 5 ** 0.5) / 2
    vertices = [(-1, t, 0), (1, t, 0), (-1, -t, 0), (1, -t, 0), (0, -1, t), (0, 1, t), (0, -1, -t), (0, 1, -t),
                (t, 0, -1), (t, 0, 1), (-t, 0, -1), (-t, 0, 1)]
    faces = [(0, 11, 5), (0, 5, 1), (0, 1, 7), (0, 7, 10), (0, 10, 11), (1, 5, 9), (5, 11, 4), (11, 10, 2),
             (10, 7, 6), (7, 1, 8), (3, 9, 4), (3, 4, 2), (3, 2, 6), (3, 6, 8), (3, 8, 9), (4, 9, 5),
             (2, 4, 11), (6, 2, 10), (8, 6, 7), (9, 8, 1)]
    vertices = [np.array(v) / np.linalg.norm(v) for v in vertices]
    for _ in range(subdivisions):
        middle = {}

        def mid(i, j):
            key = (min(i, j), max(i, j))
            if key not in middle:
                m = vertices[i] + vertices[j]
                vertices.append(m / np.linalg.norm(m))
                middle[key] = len(vertices) - 1
            return middle[key]

        faces = [f for a, b, c in faces
                 for f in ((a, mid(a, b), mid(c, a)), (b, mid(b, c), mid(a, b)), (c, mid(c, a), mid(b, c)),
                           (mid(a, b), mid(b, c), mid(c, a)))]
    return np.array(vertices), np.array(faces)


def test_vertex_curvatures_of_a_mesh():
    vertices, faces = icosphere(4)
    for kwargs in ({}, {"rings": 2}, {"radius": 0.2}, {"estimator": "paper"}):
        layer = cas.vertex_curvatures(3 * vertices, faces, **kwargs)
        assert np.abs(layer.H - 1 / 3).max() < 0.01, kwargs
        assert np.abs(np.einsum("ij,ij->i", layer.normal, vertices) - 1).max() < 1e-3
        assert layer.source is None and "source" not in layer.keys()
    inverted = cas.vertex_curvatures(vertices, faces[:, ::-1])
    assert (inverted.H < 0).all()


def test_noise_and_denoise():
    points, normals, _ = ellipsoid(20000, (1.0, 1.0, 1.0), noise=0.0)
    spacing = cas.estimate_noise(points).spacing
    noisy, _, _ = ellipsoid(20000, (1.0, 1.0, 1.0), noise=0.3 * spacing)
    estimate = cas.estimate_noise(noisy)
    assert isinstance(estimate, float) and abs(estimate - 0.3) < 0.05 and estimate.calls_for_denoising
    smoothed = cas.denoise(noisy)
    assert smoothed.shape == noisy.shape and smoothed is not noisy
    before = np.abs(np.linalg.norm(noisy, axis=1) - 1).mean()
    after = np.abs(np.linalg.norm(smoothed, axis=1) - 1).mean()
    assert after < 0.5 * before
    assert np.array_equal(cas.denoise(noisy, neighbors=30), cas.denoise(noisy, 30))


def test_read_point_cloud():
    points, normals = cas.read_point_cloud(scan_path("kitten.xyz"))
    assert points.shape == normals.shape and points.shape[1] == 3 and len(points) > 1000
    expected = np.loadtxt(scan_path("kitten.xyz"))
    assert np.array_equal(points, expected[:, :3]) and np.array_equal(normals, expected[:, 3:])


def test_help_shows_docstrings():
    for function in (cas.multiscale_curvatures, cas.ConformalAlphaShape, cas.ConformalAlphaShape.surface,
                     cas.vertex_curvatures, cas.estimate_noise, cas.denoise, cas.Result.write_ply,
                     cas.Result.to_structured, cas.Result.to_dataframe, cas.read_point_cloud, cas.read_curvatures,
                     cas.Layer.colors, cas.Result.write_las, cas.PointCloud):
        assert function.__doc__ and len(function.__doc__) > 60, function
    assert "Parameters" in cas.multiscale_curvatures.__doc__ and "Raises" in cas.multiscale_curvatures.__doc__


def test_copies_are_merged_and_unoriented_normals_warn():
    """Points written twice are merged (each copy gets its point's values);
    normals of random signs orient as no normals, with a warning."""
    points, normals, _ = ellipsoid(6000, (1.5, 1.0, 0.75), noise=0.002)
    plain = cas.multiscale_curvatures(points, radii=("auto", "4s"))
    assert plain.merged == 0
    copied = cas.multiscale_curvatures(np.vstack([points, points[::10]]), radii=("auto", "4s"))
    assert copied.merged == 600
    for name in plain.layers:
        assert np.array_equal(copied[name].H[:6000], plain[name].H, equal_nan=True)
        assert np.array_equal(copied[name].H[6000:], plain[name].H[::10], equal_nan=True)
    signs = np.random.default_rng(4).choice([-1.0, 1.0], size=(6000, 1))
    with pytest.warns(UserWarning, match="oriented as without normals"):
        unoriented = cas.multiscale_curvatures(points, normals * signs, radii=("auto", "4s"))
    for name in plain.layers:
        same = np.einsum("ij,ij->i", unoriented[name].normal, plain[name].normal) > 0
        assert same.mean() >= 0.995, name
        assert unoriented[name].surface["sheets_with_inconsistent_normals"] >= 1
        assert unoriented[name].surface["normal_agreement"] < 0.6
