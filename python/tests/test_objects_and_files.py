"""What a Python user expects of the module's objects and files: the mode of
the files written and errors naming the caller's path; a curvatures.ply read
back into a Result; repr, len and pickling; a plain ValueError naming the
minimum or the argument for small and degenerate inputs; numpy, pandas and
Open3D-ready arrays. Small clouds: the file runs in a few seconds."""
import os
import pickle
import stat

import numpy as np
import pytest

import conformal_alpha_shapes as cas
from conformal_alpha_shapes import tile_io
from conftest import ellipsoid

POINTS, NORMALS, _ = ellipsoid(2000, (1.5, 1.0, 0.75), noise=0.002)


@pytest.fixture(scope="module")
def result():
    return cas.multiscale_curvatures(POINTS, radii=("auto", "4s"))


@pytest.fixture
def umask_022():
    old = os.umask(0o022)
    yield
    os.umask(old)


def mode(path):
    return stat.S_IMODE(os.stat(path).st_mode)


def test_written_files_have_a_new_files_mode(result, tmp_path, umask_022):
    result.write_ply(tmp_path / "float.ply", precision="float32")
    result.write_ply(tmp_path / "double.ply")
    records = np.zeros(3, dtype=tile_io.part_dtype(["r4s"]))
    tile_io.write_part(str(tmp_path / "part.ply"), records, ["r4s"], {"r4s": "a = 1 (auto), radius 0.1"})
    tile_io.merge_parts(str(tmp_path / "merged.ply"), [str(tmp_path / "part.ply")], ["r4s"],
                        {"r4s": "a = 1 (auto), radius 0.1"}, 3)
    tile_io.write_manifest(str(tmp_path / "manifest.json"), {"a": 1})
    tile_io.save_array(str(tmp_path / "values.npy"), np.arange(3.0))
    names = sorted(os.listdir(tmp_path))
    assert names == ["double.ply", "float.ply", "manifest.json", "merged.ply", "part.ply", "values.npy"]
    for name in names:
        assert mode(tmp_path / name) == 0o644, name
    os.umask(0o077)
    result.write_ply(tmp_path / "private.ply")
    assert mode(tmp_path / "private.ply") == 0o600


def test_errors_name_the_callers_path(result, tmp_path):
    target = tmp_path / "missing_folder" / "curvatures.ply"
    for precision in ("float32", "float64"):
        with pytest.raises(FileNotFoundError) as error:
            result.write_ply(target, precision=precision)
        assert error.value.filename == str(target) and ".part" not in str(error.value)
    with pytest.raises(FileNotFoundError) as error:
        tile_io.write_manifest(str(target), {})
    assert error.value.filename == str(target)
    (tmp_path / "a_folder").mkdir()
    with pytest.raises(IsADirectoryError) as error:
        result.write_ply(tmp_path / "a_folder")
    assert error.value.filename == str(tmp_path / "a_folder") and ".part" not in str(error.value)
    assert os.listdir(tmp_path) == ["a_folder"] and os.listdir(tmp_path / "a_folder") == []
    with pytest.raises(ValueError, match="precision must be 'float32' or 'float64'"):
        result.write_ply(tmp_path / "x.ply", precision="half")


def test_read_curvatures_gives_back_the_result(result, tmp_path):
    path = result.write_ply(tmp_path / "double.ply")
    assert path == str(tmp_path / "double.ply")
    again = cas.read_curvatures(path)
    assert again == result  # to the bit: points, outliers, decisions, every layer's arrays and reports
    assert again.spacing == result.spacing and again["rauto"].surface["faces"] == result["rauto"].surface["faces"]
    assert cas.read_curvatures(again.write_ply(tmp_path / "double2.ply")) == result
    assert (tmp_path / "double2.ply").read_bytes() == (tmp_path / "double.ply").read_bytes()


def test_read_curvatures_of_the_programs_float_file(result, tmp_path):
    result.write_ply(tmp_path / "float.ply", precision="float32")
    again = cas.read_curvatures(tmp_path / "float.ply")
    assert again != result and again.layers == result.layers
    assert np.array_equal(again.points, result.points) and np.array_equal(again.outlier, result.outlier)
    for name in result.layers:
        for key in ("normal", "H", "K", "k1", "k2", "d1", "d2", "radius", "distance"):
            theirs = result[name][key].astype(np.float32).astype(np.float64)
            assert np.array_equal(again[name][key], theirs, equal_nan=True), (name, key)
        assert np.array_equal(again[name].source, result[name].source)
        assert again[name].description == result[name].description
        assert again[name].a == pytest.approx(result[name].a, rel=1e-5)
    assert again.spacing is None and again.noise is None and again.denoised is None
    assert "spacing" not in repr(again)
    again.write_ply(tmp_path / "float2.ply", precision="float32")
    # and its values as doubles read back to the bit
    assert cas.read_curvatures(again.write_ply(tmp_path / "double.ply")) == again
    assert (tmp_path / "float2.ply").read_bytes() == (tmp_path / "float.ply").read_bytes()


def test_read_curvatures_refuses_other_files(tmp_path):
    with pytest.raises(FileNotFoundError):
        cas.read_curvatures(tmp_path / "nowhere.ply")
    text = tmp_path / "text.ply"
    text.write_text("ply\nformat ascii 1.0\nelement vertex 1\nproperty float x\nend_header\n0\n")
    with pytest.raises(ValueError, match="text.ply.*not binary PLY"):
        cas.read_curvatures(text)
    mesh = tmp_path / "mesh.ply"
    mesh.write_bytes(b"ply\nformat binary_little_endian 1.0\nelement vertex 0\nproperty double x\n"
                     b"property double y\nproperty double z\nelement face 0\n"
                     b"property list uchar int vertex_indices\nend_header\n")
    with pytest.raises(ValueError, match="mesh.ply.*one vertex element"):
        cas.read_curvatures(mesh)
    (tmp_path / "other.txt").write_text("not a ply\n")
    with pytest.raises(ValueError, match="other.txt: not a PLY file"):
        cas.read_curvatures(tmp_path / "other.txt")


def test_shape_repr_len_points_and_pickle(tmp_path):
    shape = cas.ConformalAlphaShape(POINTS)
    assert len(shape) == len(POINTS) and shape.dimension == 3
    assert repr(shape) == f"<ConformalAlphaShape: {len(POINTS)} points, dimension 3, " \
                          f"{len(shape.spectrum())} values in the spectrum>"
    assert np.array_equal(shape.points, POINTS) and not shape.points.flags.writeable
    sizes = shape.local_feature_sizes
    assert sizes.shape == (len(POINTS),) and (sizes > 0).all()
    copy = pickle.loads(pickle.dumps(shape))
    assert np.array_equal(copy.spectrum(), shape.spectrum()) and np.array_equal(copy.points, shape.points)
    assert copy.suggest_scale() == shape.suggest_scale()
    for mine, theirs in zip(copy.surface(), shape.surface()):
        assert np.array_equal(mine, theirs)
    given = cas.ConformalAlphaShape(POINTS, local_scales=np.full(len(POINTS), 0.05))
    assert np.array_equal(pickle.loads(pickle.dumps(given)).spectrum(), given.spectrum())
    assert np.array_equal(given.local_feature_sizes, np.full(len(POINTS), 0.05))


def _spectrum_size(shape):
    return len(shape.spectrum()), shape.suggest_scale()


def test_a_dask_worker_process_receives_a_shape():
    """The shape goes to another process by pickle, as Dask sends a task's arguments."""
    from distributed import Client, LocalCluster
    shape = cas.ConformalAlphaShape(POINTS)
    try:
        cluster = LocalCluster(n_workers=1, threads_per_worker=1, processes=True, host="127.0.0.1",
                               dashboard_address=None)
    except Exception as e:  # a test whose service cannot start fails
        pytest.fail(f"a Dask LocalCluster of 1 process did not start: {e!r}")
    with cluster, Client(cluster) as client:
        assert client.submit(_spectrum_size, shape).result(timeout=120) == _spectrum_size(shape)


def test_the_shape_keeps_its_own_points():
    points = POINTS.copy()
    shape = cas.ConformalAlphaShape(points)
    points[:] = 0
    assert np.array_equal(shape.points, POINTS)


def test_every_public_object_pickles_and_has_a_repr(result):
    noise = cas.estimate_noise(POINTS)
    again = pickle.loads(pickle.dumps(noise))
    assert again == noise and again.spacing == noise.spacing and again.noise_24 == noise.noise_24
    assert again.calls_for_denoising == noise.calls_for_denoising and repr(again) == repr(noise)
    assert pickle.loads(pickle.dumps(result)) == result
    layer = result["r4s"]
    assert pickle.loads(pickle.dumps(layer)) == layer and len(layer) == len(POINTS)
    assert repr(layer).startswith("<Layer 'r4s', a = ") and repr(result).startswith(f"<Result: {len(POINTS)} points")
    mesh_layer = cas.vertex_curvatures(*cas.ConformalAlphaShape(POINTS).surface()[:2])
    assert pickle.loads(pickle.dumps(mesh_layer)) == mesh_layer and repr(mesh_layer).startswith("<Layer: ")


def test_version():
    import re
    assert re.fullmatch(r"\d+\.\d+\.\d+", cas.__version__)


@pytest.mark.parametrize("n", [0, 1, 3])
def test_fewer_than_4_points(n):
    points = np.random.default_rng(n).normal(size=(n, 3))
    for function in (cas.multiscale_curvatures, cas.front_closing_values, cas.ConformalAlphaShape):
        with pytest.raises(ValueError, match=r"\b%d points?; at least 4 that are not coplanar" % n):
            function(points)


@pytest.mark.parametrize("n", [4, 20, 24])
def test_fewer_than_25_points(n):
    points = np.random.default_rng(n).normal(size=(n, 3))
    for function in (cas.estimate_noise, cas.denoise):
        with pytest.raises(ValueError, match=f"{n} points; at least 25 are needed .*24 nearest neighbors"):
            function(points)
    with pytest.raises(ValueError, match=f"{n} points; radii in sample spacings \\(auto, 2s, 4s, 8s, 16s\\) "
                                         "need .* at least 25 points; give the radii as lengths"):
        cas.multiscale_curvatures(points)
    # what needs no spacing still works
    r = cas.multiscale_curvatures(points, radii=[1.0], rings=[1])
    assert r.layers == ("r1", "k1")
    r = cas.multiscale_curvatures(points, spacing=0.5, noise=0.0, radii=["4s"])
    assert r["r4s"].description.endswith("radius 2")  # 4 spacings of 0.5
    assert len(cas.front_closing_values(points)) == n and len(cas.ConformalAlphaShape(points)) == n


def test_points_whose_spacing_cannot_be_estimated():
    coincident = np.repeat(np.random.default_rng(2).normal(size=(5, 3)), 10, axis=0)
    with pytest.raises(ValueError, match="estimate_noise: the noise and the sample spacing cannot be estimated "
                                         "on these 50 points"):
        cas.estimate_noise(coincident)
    with pytest.raises(ValueError, match="denoise: .* could not be estimated on these 50 points"):
        cas.denoise(coincident)
    with pytest.raises(ValueError, match="multiscale_curvatures: radii in sample spacings .* could not be "
                                         "estimated on these 50 points"):
        cas.multiscale_curvatures(coincident)


def test_scales_out_of_range_name_the_argument():
    shape = cas.ConformalAlphaShape(POINTS[:500])
    for a in (float("nan"), -1.0, -1e-300):
        for method in (shape.surface, shape.classify_facets):
            with pytest.raises(ValueError, match=r"the scale a must be >= 0"):
                method(a)
    with pytest.raises(TypeError, match="the scale a must be a number"):
        shape.surface("1")
    assert len(shape.surface(0.0)[1]) == 0  # below every value: empty, as documented
    for q in (float("nan"), -0.1, 1.5):
        with pytest.raises(ValueError, match=r"the quantile q must be in \[0, 1\]"):
            shape.alpha_at_quantile(q)
    for coverage in (float("nan"), 0, 1.5):
        with pytest.raises(ValueError, match=r"coverage must be in \(0, 1\]"):
            shape.suggest_scale(coverage=coverage)


def test_structured_dataframe_and_colors(result):
    records = result.to_structured("r4s")
    assert records.dtype.names[:6] == ("X", "Y", "Z", "NormalX", "NormalY", "NormalZ")
    assert np.array_equal(records["H"], result["r4s"].H, equal_nan=True)
    try:
        import pandas
    except ImportError:  # pandas is optional: without it the method says what to install
        with pytest.raises(ImportError, match="python3-pandas"):
            result.to_dataframe("r4s")
    else:
        frame = result.to_dataframe("r4s")
        assert isinstance(frame, pandas.DataFrame) and list(frame.columns) == list(records.dtype.names)
        assert np.array_equal(frame["k1"].to_numpy(), result["r4s"].k1, equal_nan=True)
    colors = result["r4s"].colors("H")
    assert colors.shape == (len(POINTS), 3) and colors.dtype == np.float64
    assert ((colors >= 0) & (colors <= 1)).all()
    H = result["r4s"].H
    assert (colors[H > 0, 0] == 1).all() and (colors[H < 0, 2] == 1).all()
    assert (colors[np.isnan(H)] == 128 / 255).all()
    with pytest.raises(ValueError, match="normal is not a value per point"):
        result["r4s"].colors("normal")
