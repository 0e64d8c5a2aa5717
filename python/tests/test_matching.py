"""Shape index, curvedness, region descriptors and matching (conformal_alpha_shapes.matching)."""
import os

import numpy as np
import pytest

import conformal_alpha_shapes as cas


def test_shape_index_convention():
    # curvatures follow the outward normal: a sphere has k1 = k2 = 1/r > 0
    assert cas.shape_index(0.5, 0.5) == 1.0
    assert cas.shape_index(-0.5, -0.5) == -1.0
    assert cas.shape_index(0.5, 0.0) == pytest.approx(0.5)
    assert cas.shape_index(0.0, -0.5) == pytest.approx(-0.5)
    assert cas.shape_index(0.5, -0.5) == 0.0
    assert np.isnan(cas.shape_index(0.0, 0.0))
    assert cas.shape_index(0.0, 0.5) == cas.shape_index(0.5, 0.0)
    assert cas.curvedness(0.5, 0.5) == 0.5
    assert cas.curvedness(0.0, 0.0) == 0.0
    s = cas.shape_index(np.array([1.0, 0.0, np.nan]), np.array([1.0, 0.0, 1.0]))
    assert s[0] == 1.0 and np.isnan(s[1]) and np.isnan(s[2])


def test_layer_shape_index_on_a_sphere():
    from conftest import fibonacci_sphere
    points, normals = fibonacci_sphere(3000, radius=2.0)
    r = cas.multiscale_curvatures(points, normals, radii=(0.8,))
    layer = r[r.layers[0]]
    assert np.nanmedian(layer.shape_index) == pytest.approx(1.0, abs=0.02)
    assert np.nanmedian(layer.curvedness) == pytest.approx(0.5, rel=0.05)


def test_farthest_point_sample():
    points = np.random.default_rng(3).random((500, 3))
    chosen = cas.farthest_point_sample(points, 50)
    assert len(set(chosen.tolist())) == 50 and chosen[0] == 0
    assert len(cas.farthest_point_sample(points, 900)) == 500


def test_bad_arguments():
    points = np.random.default_rng(3).random((50, 3))
    layer = {"k1": np.ones(50), "k2": np.ones(50), "radius": np.ones(50)}
    with pytest.raises(ValueError, match="rings must be increasing"):
        cas.region_descriptors(points, layer, 5, rings=(3, 2))
    with pytest.raises(ValueError, match="50 points but 49 values"):
        cas.region_descriptors(points, {k: v[:49] for k, v in layer.items()}, 5)
    with pytest.raises(ValueError, match="point indices"):
        cas.region_descriptors(points, layer, np.array([0, 50]))
    a = cas.region_descriptors(points, layer, 5)
    b = cas.region_descriptors(points, layer, 5, rings=(2.0, 4.0))
    with pytest.raises(ValueError, match="different layouts"):
        cas.match_regions(a, b)
    with pytest.raises(ValueError, match="thinning"):
        cas.region_descriptors(points, layer, 5, thinning=0)
    # every point counted or one in three beyond dense_radius: the same layout, so comparable
    assert cas.region_descriptors(points, layer, 5, thinning=1).descriptors.shape == a.descriptors.shape
    with pytest.raises(ValueError, match="ring_weights"):
        cas.region_descriptors(points, layer, 5, ring_weights=(1.0, 2.0))
    with pytest.raises(ValueError, match="different layouts"):
        cas.match_regions(a, cas.region_descriptors(points, layer, 5, ring_weights="equal"))


def test_histogram_distances_follow_the_bins_order():
    # one layer, one ring: a region whose points all have one shape index; the earth mover's distance
    # grows with the gap between the shape indices, as a share of [-1, 1] (chi-square would not)
    points = np.random.default_rng(5).random((40, 3))
    values = np.repeat([1.0, 0.8, 0.0, -1.0], 10)  # shape index 1, 0.8, 0, -1 from k1 = 1, k2 = ...
    k2 = np.tan(values * np.pi / 2 - np.pi / 4) * 1.0
    k2 = np.where(values == 1.0, 1.0, np.where(values == -1.0, -1.0, k2))
    k1 = np.where(values == -1.0, -1.0, 1.0)
    layer = {"k1": k1, "k2": k2, "radius": np.ones(40)}
    assert np.allclose(cas.shape_index(k1, k2), values)
    regions = cas.region_descriptors(points, layer, np.array([0]), rings=(10.0,))
    each = [cas.region_descriptors(points[i:i + 10], {k: v[i:i + 10] for k, v in layer.items()}, np.array([0]),
                                   rings=(10.0,)) for i in range(0, 40, 10)]
    d = [cas.histogram_distances(each[0], other, balance=False)[0, 0] for other in each]
    assert d[0] == 0 and d[1] < d[2] < d[3] <= 1
    assert regions.histograms == 2 and list(regions.histogram_bins) == [10, 6]


def test_crambin_matches_a_moved_copy():
    """The crambin surface (8,142 points) against a rotated, translated copy, each with its own
    curvature; 100 farthest-point centres against 800 candidates of the copy sampled from
    another start. Measured: top-1 1.00, top-10 1.00 (1.00 and 1.00 re-ranked by the registration),
    all the matches consistent, motion to 0.19 A (the candidates are about 1 A apart)."""
    path = os.path.join(os.environ.get("CAS3_SOURCE_DIR", "."),
                        "examples/Conformal_alpha_shapes_3/data/1crn_surface.xyz")
    data = np.loadtxt(path)
    points, normals = data[:, :3], data[:, 3:]
    angle = 0.9
    rotation = np.array([[np.cos(angle), 0, np.sin(angle)], [0, 1, 0], [-np.sin(angle), 0, np.cos(angle)]])
    moved = points @ rotation.T + np.array([10.0, -3.0, 7.0])
    radii = (1.5, 3.0, 6.0)
    ra = cas.multiscale_curvatures(points, normals, radii=radii)
    rb = cas.multiscale_curvatures(moved, normals @ rotation.T, radii=radii)
    a = cas.region_descriptors(points, ra, 100, normals=normals)
    b = cas.region_descriptors(moved, rb, cas.farthest_point_sample(moved, 800, first=4000),
                               normals=normals @ rotation.T)
    matches = cas.match_regions(a, b, top=10)
    truth = moved[a.centers]
    found = np.linalg.norm(moved[matches.candidates] - truth[:, None, :], axis=2) <= 3.0
    reranked = np.linalg.norm(moved[matches.reranked] - truth[:, None, :], axis=2) <= 3.0
    assert np.mean(reranked[:, 0]) >= 0.99
    assert np.mean(found[:, 0]) >= 0.95
    assert np.mean(np.any(found, axis=1)) >= 0.99
    assert matches.consistent >= 0.9
    # B placed onto A: the inverse of the motion
    assert np.max(np.abs(matches.transform(moved) - points)) < 0.3
    assert (matches.scores[:, 1:] >= matches.scores[:, :-1]).all()


def test_one_thread_or_all_give_the_same():
    """The C++ descriptors, distances and matches run on TBB's threads with the serial results."""
    from conftest import fibonacci_sphere
    points, normals = fibonacci_sphere(4000, radius=15.0)
    u = points / 15.0
    layer = {"k1": 0.3 * np.sin(9 * u[:, 0] + 7 * u[:, 1]) + 0.05, "k2": 0.3 * np.cos(8 * u[:, 1] - 11 * u[:, 2]),
             "radius": np.full(4000, 2.0)}
    runs = []
    for threads in (1, None):
        a = cas.region_descriptors(points, layer, 200, normals=normals, threads=threads)
        b = cas.region_descriptors(points, layer, cas.farthest_point_sample(points, 600, first=7), normals=normals,
                                   threads=threads)
        runs.append((a.descriptors, cas.match_regions(a, b, threads=threads)))
    assert np.array_equal(runs[0][0], runs[1][0])
    assert np.array_equal(runs[0][1].candidates, runs[1][1].candidates)
    assert np.array_equal(runs[0][1].scores, runs[1][1].scores)
    assert np.array_equal(runs[0][1].rotation, runs[1][1].rotation)
    with pytest.raises(ValueError, match="threads"):
        cas.region_descriptors(points, layer, 5, threads=0)
