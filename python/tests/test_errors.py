"""Bad input raises a Python exception with the C++ message, never crashes,
and never leaves a half-written file."""
import os

import numpy as np
import pytest

import conformal_alpha_shapes as cas
from conftest import fibonacci_sphere

POINTS, _ = fibonacci_sphere(500)


@pytest.mark.parametrize("value", [np.nan, np.inf, -np.inf])
def test_non_finite_coordinates_name_the_index(value):
    points = POINTS.copy()
    points[123, 1] = value
    for call in (cas.multiscale_curvatures, cas.ConformalAlphaShape):
        with pytest.raises(ValueError, match="123"):
            call(points)


@pytest.mark.parametrize("points", [POINTS[:3], np.zeros((0, 3)), np.repeat(POINTS[:1], 50, axis=0),
                                    np.column_stack([POINTS[:, :2], np.zeros(500)])],
                         ids=["three points", "no point", "one point repeated", "coplanar"])
def test_points_that_do_not_span_3d(points):
    with pytest.raises(ValueError, match="3D|span|points"):
        cas.multiscale_curvatures(points)
    with pytest.raises(ValueError):
        cas.ConformalAlphaShape(points)


@pytest.mark.parametrize("kwargs, message", [
    ({"scales": ("-1",)}, "scales: not a scale: '-1'"),
    ({"scales": (0,)}, "scales: a scale must be above 0"),
    ({"scales": ("150%",)}, "scales: not a scale: '150%'"),
    ({"scales": ()}, "scales: no scale given"),
    ({"radii": ("0",)}, "radii: not a radius: '0'"),
    ({"radii": (-0.5,)}, "radii: not a radius"),
    ({"radii": ("4x",)}, "radii: not a radius: '4x'"),
    ({"radii": (), "rings": ()}, "no neighborhood"),
    ({"rings": (0,)}, "rings: not a ring size from 1 to 100: '0'"),
    ({"rings": (101,)}, "rings: not a ring size"),
    ({"estimator": "jet"}, "estimator: unknown estimator 'jet' \\(quadric, euler-least-squares, paper\\)"),
    ({"denoise": "maybe"}, "denoise: unknown mode 'maybe'"),
    ({"denoise_neighbors": 3}, "denoise_neighbors: not a neighbor count >= 7: '3'"),
    ({"extraction": "poisson"}, "extraction: unknown extraction 'poisson' \\(front, solid\\)"),
    ({"threads": 0}, "threads must be >= 1"),
    ({"radii": ("4s,8s",)}, "one value per item"),
])
def test_bad_options_raise_value_error(kwargs, message):
    with pytest.raises(ValueError, match=message):
        cas.multiscale_curvatures(POINTS, **kwargs)


@pytest.mark.parametrize("kwargs", [{"scales": (None,)}, {"rings": (2.5,)}, {"rings": ("2",)}, {"radii": (True,)},
                                    {"estimator": 1}, {"threads": 1.5}, {"progress": 3},
                                    {"denoise_neighbors": "30"}])
def test_bad_option_types_raise_type_error(kwargs):
    with pytest.raises(TypeError):
        cas.multiscale_curvatures(POINTS, **kwargs)


@pytest.mark.parametrize("points, error, message", [
    (POINTS[:, :2], ValueError, r"points must be an \(N, 3\) array, got shape \(500, 2\)"),
    (POINTS.ravel(), ValueError, r"points must be an \(N, 3\) array, got shape \(1500,\)"),
    (POINTS[None], ValueError, r"\(N, 3\)"),
    (POINTS.astype(complex), TypeError, "real numbers, got dtype complex128"),
    (POINTS.astype(object), TypeError, "real numbers, got dtype object"),
    (POINTS > 0, TypeError, "real numbers, got dtype bool"),
    ("points.xyz", TypeError, "real numbers"),
])
def test_wrong_shapes_and_types(points, error, message):
    for call in (cas.multiscale_curvatures, cas.ConformalAlphaShape, cas.estimate_noise, cas.denoise):
        with pytest.raises(error, match=message):
            call(points)


@pytest.mark.parametrize("kwargs, message", [
    ({"spacing": 0.1}, "spacing and noise are given together"),
    ({"noise": 0.1}, "spacing and noise are given together"),
    ({"spacing": 0.0, "noise": 0.1}, "spacing must be finite and positive"),
    ({"spacing": np.inf, "noise": 0.1}, "spacing must be finite and positive"),
    ({"spacing": np.nan, "noise": 0.1}, "spacing must be finite and positive"),
    ({"spacing": 0.1, "noise": -0.5}, "noise must be a number, 0 or more"),
    ({"spacing": 0.1, "noise": np.nan}, "noise must be a number, 0 or more"),
])
def test_bad_spacing_and_noise(kwargs, message):
    with pytest.raises(ValueError, match=message):
        cas.multiscale_curvatures(POINTS, **kwargs)
    with pytest.raises(TypeError):
        cas.multiscale_curvatures(POINTS, spacing="0.1", noise=0.1)


def test_wrong_normals():
    with pytest.raises(ValueError, match=r"normals must be an \(N, 3\) array with N = 500"):
        cas.multiscale_curvatures(POINTS, POINTS[:10])
    with pytest.raises(ValueError, match=r"normals must be an \(N, 3\) array"):
        cas.multiscale_curvatures(POINTS, POINTS[:, :2])


def test_shape_errors():
    shape = cas.ConformalAlphaShape(POINTS)
    for q in (-0.1, 1.5, np.nan):
        with pytest.raises(ValueError):
            shape.alpha_at_quantile(q)
    with pytest.raises(ValueError):
        shape.suggest_scale(coverage=0)
    with pytest.raises(ValueError, match="extraction: unknown extraction"):
        shape.surface(extraction="poisson")
    with pytest.raises(ValueError):
        shape.classify_facets(-1)
    with pytest.raises(ValueError, match="index 7|7"):
        scales = np.ones(500)
        scales[7] = 0
        cas.ConformalAlphaShape(POINTS, local_scales=scales)
    with pytest.raises(ValueError, match=r"local_scales must be an \(N,\) array"):
        cas.ConformalAlphaShape(POINTS, local_scales=np.ones(499))


def test_mesh_errors():
    vertices = POINTS[:4]
    with pytest.raises(ValueError, match="names vertex 9"):
        cas.vertex_curvatures(vertices, [[0, 1, 9]])
    with pytest.raises(ValueError, match="repeats a vertex"):
        cas.vertex_curvatures(vertices, [[0, 1, 1]])
    with pytest.raises(ValueError, match=r"faces must be an \(F, 3\) array"):
        cas.vertex_curvatures(vertices, [[0, 1, 2, 3]])
    with pytest.raises(TypeError, match="integers"):
        cas.vertex_curvatures(vertices, [[0.0, 1.0, 2.0]])
    with pytest.raises(ValueError, match="oriented 2-manifold"):
        cas.vertex_curvatures(vertices, [[0, 1, 2], [0, 1, 2]])
    with pytest.raises(ValueError, match="give rings or radius"):
        cas.vertex_curvatures(vertices, [[0, 1, 2]], rings=2, radius=0.1)
    with pytest.raises(ValueError, match="ring"):
        cas.vertex_curvatures(vertices, [[0, 1, 2]], rings=0)
    with pytest.raises(ValueError, match="radius"):
        cas.vertex_curvatures(vertices, [[0, 1, 2]], radius=-1.0)


def test_denoise_and_read_errors(tmp_path):
    with pytest.raises(ValueError, match="neighbors must be >= 7"):
        cas.denoise(POINTS, neighbors=3)
    with pytest.raises(ValueError, match="nowhere.xyz"):
        cas.read_point_cloud(tmp_path / "nowhere.xyz")
    bad = tmp_path / "bad.xyz"
    bad.write_text("0 0 0\n1 x 2\n")
    with pytest.raises(ValueError, match="bad.xyz.*2|line 2"):
        cas.read_point_cloud(bad)


def test_write_ply_never_leaves_a_half_written_file(tmp_path):
    r = cas.multiscale_curvatures(POINTS, radii=("4s",))
    with pytest.raises(OSError):
        r.write_ply(tmp_path / "missing_folder" / "curvatures.ply")
    r["r4s"].H = r["r4s"].H[:10]  # a broken result: the writer refuses it
    with pytest.raises(ValueError, match="H has not one value per point"):
        r.write_ply(tmp_path / "curvatures.ply")
    assert os.listdir(tmp_path) == []
