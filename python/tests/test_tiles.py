"""Tiled processing on Dask (conformal_alpha_shapes.tiles): a tiled run gives
the answer of one run; the scheduler-and-workers path; seams; faults; bad
input; atomic writes. Small clouds, so that the file runs in about 100 s on
two cores; a service that cannot start fails the test."""
import os
import re
import signal
import socket
import subprocess
import sys
import threading
import time

import numpy as np
import pytest

import conformal_alpha_shapes as cas
from conformal_alpha_shapes import tile_io, tile_partition, tiles

from conftest import fibonacci_sphere, scan_path


def scene(n, seed=1, noise=0.1):
    """A noisy scene: a closed ellipsoid above an open wavy sheet (both across
    several tiles), and 5 isolated far outliers; the points and, per point,
    0 ellipsoid, 1 sheet, 2 outlier."""
    rng = np.random.default_rng(seed)
    closed = n // 3
    unit, _ = fibonacci_sphere(closed)
    ellipsoid = unit * np.array([1.0, 0.7, 0.5]) + np.array([0, 0, 1.2])
    side = int(np.sqrt(n - closed))
    spacing = 4 / side
    grid = np.stack(np.meshgrid(np.linspace(-2, 2, side), np.linspace(-2, 2, side)), -1).reshape(-1, 2)
    grid = grid + rng.uniform(-0.3, 0.3, grid.shape) * spacing
    sheet = np.column_stack([grid, 0.15 * np.sin(1.5 * grid[:, 0]) * np.cos(grid[:, 1])])
    points = np.vstack([ellipsoid, sheet])
    points = points + rng.normal(0, noise * spacing, points.shape)
    far = np.array([[0, 0, 4], [1.5, -1, 4.5], [-1.5, 1, 5], [3, 3, 3], [-3, -3, -2.0]])
    label = np.concatenate([np.zeros(len(ellipsoid)), np.ones(len(sheet)), np.full(len(far), 2)])
    order = rng.permutation(len(points) + len(far))
    return np.vstack([points, far])[order], label[order].astype(int)


def read_merged(folder, names):
    with open(os.path.join(folder, "curvatures.ply"), "rb") as f:
        head = f.read(1 << 16)
    offset = head.index(b"end_header\n") + len(b"end_header\n")
    return np.memmap(os.path.join(folder, "curvatures.ply"), dtype=tile_io.part_dtype(names, False), mode="r",
                     offset=offset)


def normals_of(records, name):
    return np.column_stack([records[f"n{axis}_{name}"] for axis in "xyz"]).astype(np.float64)


@pytest.fixture(scope="module")
def client():
    """A LocalCluster of 2 worker processes, one thread each, on 127.0.0.1."""
    from distributed import Client, LocalCluster
    try:
        cluster = LocalCluster(n_workers=2, threads_per_worker=1, processes=True, host="127.0.0.1",
                               dashboard_address=None)
    except Exception as e:  # a test whose service cannot start fails
        pytest.fail(f"a Dask LocalCluster of 2 processes did not start: {e!r}")
    c = Client(cluster)
    yield c
    c.close()
    cluster.close()


@pytest.fixture(scope="module")
def scene_run(client, tmp_path_factory):
    """An 80k-point scene in 8 tiles, merged, and one run of the module on it."""
    folder = tmp_path_factory.mktemp("scene")
    points, label = scene(80_000)
    np.save(folder / "scene.npy", points)
    summary = tiles.process_tiles(folder / "scene.npy", folder / "out", tile_points=10_000, client=client,
                                  merge=True, quiet=True)
    one = cas.multiscale_curvatures(points)
    return points, label, summary, one, folder


def assert_same_answer(points, one, summary, folder, a_tolerance, h_tolerance_99=None):
    """A tiled run's merged file (in ``folder``) against ``one`` run of the
    module; with ``h_tolerance_99``, H at 99% of the points within that
    share of the median |H|."""
    assert summary["spacing"] == pytest.approx(one.spacing, rel=1e-12)
    assert summary["noise"] == pytest.approx(one.noise, rel=1e-12)
    assert summary["denoised"] == one.denoised
    # the automatic scale: the local closing values of all tiles pooled
    assert summary["a"][0] == pytest.approx(one["rauto"].a, rel=a_tolerance)
    merged = read_merged(folder, summary["layers"])
    assert len(merged) == len(points)
    assert np.array_equal(merged["x"], points[:, 0]) and np.array_equal(merged["z"], points[:, 2])
    assert np.array_equal(merged["outlier"].astype(bool), one.outlier)
    indices = np.concatenate([tile_io.read_part(os.path.join(folder, "parts", f"part_{t:05d}.ply"),
                                                summary["layers"])["input_index"] for t in range(summary["tiles"])])
    assert np.array_equal(np.sort(indices.astype(np.int64)), np.arange(len(points)))  # every index once
    for name in one.layers:
        mine, theirs = normals_of(merged, name), one[name].normal
        dot = np.einsum("ij,ij->i", mine, theirs)
        valid = np.isfinite(dot)
        assert np.mean(dot[valid] > 0) >= 0.995, name
        H, reference = merged[f"H_{name}"].astype(np.float64), one[name].H
        both = np.isfinite(H) & np.isfinite(reference)
        assert both.sum() >= 0.99 * (~one.outlier).sum(), name
        # the parts' floats: the large radii's centers are those of one run too
        relative = np.median(np.abs(H[both] - reference[both])) / np.median(np.abs(reference[both]))
        assert relative <= 1e-6, (name, relative)
        if h_tolerance_99 is not None:
            # the points near the tiles' borders too, which a halo narrower
            # than the largest radius changes while the median stays put
            worst = np.quantile(np.abs(H[both] - reference[both]), 0.99) / np.median(np.abs(reference[both]))
            assert worst <= h_tolerance_99, (name, worst)
            # and their uncertainty, whose bias rates are pooled over the
            # vertices within 5 spacings: a vertex whose fits differ moves
            # the sigma of those around it
            sigma, reference = merged[f"H_sigma_{name}"].astype(np.float64), one[name].H_sigma
            both = np.isfinite(sigma) & np.isfinite(reference)
            worst = np.quantile(np.abs(sigma[both] - reference[both]) / reference[both], 0.99)
            assert worst <= 10 * h_tolerance_99, (name, "H_sigma", worst)


def test_tiled_run_equals_one_run(scene_run):
    """The automatic scale within 0.2% of one run's (measured: 0.012%), and
    H at 99% of the points within 1e-5 of the median |H| in every layer
    (measured: under 1e-6; with a third of the halo, 0.1 in r16s), and
    its sigma within 1e-4 of itself (measured: 4e-5)."""
    points, _, summary, one, folder = scene_run
    assert summary["tiles"] == 8
    assert_same_answer(points, one, summary, folder / "out", 0.002, h_tolerance_99=1e-5)


def test_normals_of_random_signs_orient_as_no_normals(client, tmp_path):
    """Normals of random signs (an unoriented estimate): each tile orients
    their sheets as without normals, and across tiles the objects that do
    not follow them are joined by their seams as without normals, so the
    sides are one run's without normals (measured: 100% in every layer; 80%
    when the tiles turn nothing, as they do with consistent normals); the
    summary says so."""
    points, _ = scene(80_000, seed=4)
    one = cas.multiscale_curvatures(points)
    normals = np.column_stack([points[:, :2] * 0, np.ones(len(points))])
    normals *= np.where(np.random.default_rng(6).random(len(points)) < 0.5, -1.0, 1.0)[:, None]
    np.save(tmp_path / "scene.npy", np.hstack([points, normals]))
    summary = tiles.process_tiles(tmp_path / "scene.npy", tmp_path / "out", tile_points=4_000, client=client,
                                  merge=True, quiet=True)
    assert summary["tiles"] == 20 and summary["objects_without_normals"] > 0
    assert "oriented as without normals" in tiles.format_summary(summary)
    merged = read_merged(tmp_path / "out", summary["layers"])
    for name in one.layers:
        dot = np.einsum("ij,ij->i", normals_of(merged, name), one[name].normal)
        valid = np.isfinite(dot)
        assert np.mean(dot[valid] > 0) >= 0.995, name


def test_a_scan_in_tiles_equals_one_run(client, tmp_path):
    """building.ply (100,000 points of uneven density, with normals) in 4 tiles:
    the automatic scale within 0.2% of one run's (measured -0.09%: a
    vertex's closing value is a value of its star, so a tile with its halo
    gives its core one run's values but where the halo changes a pole)."""
    points, normals = cas.read_point_cloud(scan_path("building.ply"))
    np.save(tmp_path / "building.npy", np.hstack([points, normals]))
    summary = tiles.process_tiles(tmp_path / "building.npy", tmp_path / "out", tile_points=25_000, client=client,
                                  merge=True, quiet=True)
    assert summary["tiles"] == 4
    assert_same_answer(points, cas.multiscale_curvatures(points, normals), summary, tmp_path / "out", 0.002)


def test_a_widely_spread_automatic_scale_is_named(client, tmp_path, scene_run):
    """b9_training.ply (an airborne town block) in 4 tiles: a few border
    vertices close through facets longer than the halo, the automatic
    scale's window of closing values spans a factor of 2.7 (the scene's:
    1.2), and the summary says that the scale may not be one run's."""
    points, _ = cas.read_point_cloud(scan_path("b9_training.ply"))
    np.save(tmp_path / "b9.npy", points)
    summary = tiles.process_tiles(tmp_path / "b9.npy", tmp_path / "out", tile_points=6_000, client=client,
                                  quiet=True)
    assert summary["tiles"] == 4 and summary["a_tail_spread"] > tiles.WIDE_TAIL, summary["a_tail_spread"]
    assert "a few far-reaching values decide it" in tiles.format_summary(summary)
    scene_summary = scene_run[2]
    assert scene_summary["a_tail_spread"] < 2, scene_summary["a_tail_spread"]
    assert "far-reaching" not in tiles.format_summary(scene_summary)


def test_open_sheets_joined_across_gaps_face_as_in_one_run(client, tmp_path):
    """b9_training.ply (roofs, walls and ground, many open sheets that one run
    joins across gaps before it votes) in 4 tiles whose halos hold the whole
    block, so that the automatic scale is one run's: every normal on one
    run's side (measured: 100%; 97.9% when each tile's objects vote alone
    through per-point cones, 98.3% with one run's vote but no groups)."""
    points, _ = cas.read_point_cloud(scan_path("b9_training.ply"))
    np.save(tmp_path / "b9.npy", points)
    summary = tiles.process_tiles(tmp_path / "b9.npy", tmp_path / "out", tile_points=6_000, client=client,
                                  halo=120, merge=True, quiet=True)
    one = cas.multiscale_curvatures(points)
    assert summary["tiles"] == 4 and summary["a"][0] == one["rauto"].a
    merged = read_merged(tmp_path / "out", summary["layers"])
    for name in one.layers:
        dot = np.einsum("ij,ij->i", normals_of(merged, name), one[name].normal)
        valid = np.isfinite(dot)
        assert np.mean(dot[valid] > 0) >= 0.999, (name, np.mean(dot[valid] > 0))


def test_the_merged_file_is_the_programs_format(scene_run):
    _, _, summary, one, folder = scene_run
    with open(folder / "out" / "curvatures.ply", "rb") as f:
        head = f.read(4096)
    reference = folder / "one.ply"
    one.write_ply(reference, precision="float32")
    with open(reference, "rb") as f:
        theirs = f.read(4096)
    end = b"end_header\n"
    mine_header, their_header = head[:head.index(end)], theirs[:theirs.index(end)]
    # the same fields; the descriptions differ only by the scale's value
    strip = lambda header: [line for line in header.split(b"\n") if not line.startswith(b"comment layer")]
    assert strip(mine_header) == strip(their_header)
    # read back into a Result, which writes the same bytes
    merged = cas.read_curvatures(folder / "out" / "curvatures.ply")
    assert merged.layers == one.layers and np.array_equal(merged.points, one.points)
    merged.write_ply(folder / "again.ply", precision="float32")
    assert (folder / "again.ply").read_bytes() == (folder / "out" / "curvatures.ply").read_bytes()


def test_the_files_have_a_new_files_mode(scene_run):
    """Parts, manifest, summary and merged file: 0666 less the umask (the run's and its workers')."""
    folder = scene_run[4] / "out"
    umask = os.umask(0)
    os.umask(umask)
    files = [os.path.join(root, name) for root, _, names in os.walk(folder) for name in names]
    assert any(path.endswith("curvatures.ply") for path in files) and any("part" in path for path in files)
    for path in files:
        assert os.stat(path).st_mode & 0o777 == 0o666 & ~umask, path


def test_a_dask_task_receives_a_shape(client):
    points, _ = fibonacci_sphere(500)
    shape = cas.ConformalAlphaShape(points)
    spectrum, count = client.submit(lambda s: (s.spectrum(), len(s)), shape, pure=False).result()
    assert np.array_equal(spectrum, shape.spectrum()) and count == 500


def test_seams_agree_and_closed_parts_point_outward(scene_run):
    points, label, summary, _, folder = scene_run
    assert summary["worst_seam_agreement"] >= 0.99
    merged = read_merged(folder / "out", summary["layers"])
    normal = normals_of(merged, "rauto")
    on = np.isfinite(normal[:, 0])
    # the closed ellipsoid spans tiles: outward
    closed = on & (label == 0)
    outward = np.einsum("ij,ij->i", normal[closed], points[closed] - np.array([0, 0, 1.2]))
    assert np.mean(outward > 0) >= 0.99
    # the open sheet: one side, up to one global flip
    sheet = on & (label == 1)
    up = np.mean(normal[sheet, 2] > 0)
    assert max(up, 1 - up) >= 0.99


def test_the_cuts_cross_sheets_rather_than_follow_them():
    """The scene's far outliers make its vertical extent the longest, and a
    horizontal cut at the median height runs along the wavy ground: the cuts
    are where their bands hold the fewest points."""
    points, label = scene(60_000)
    band = 0.1
    tree = tile_partition.split(points, 4, 0, band)
    cores = tile_partition.assign(tree, points, 0.0)
    halos = tile_partition.assign(tree, points, band)
    assert sorted(np.concatenate(list(cores.values()))) == list(range(len(points)))
    added = sum(len(halos[t]) - len(cores[t]) for t in cores) / len(points)
    # a vertical cut through the 4 x 4 ground and the ellipsoid adds about
    # 2 band / 4 of each per cut (three cuts); a horizontal one most of the ground
    assert added < 0.2, f"the halos add {added:.0%} of the points: a cut runs along a sheet"
    assert min(len(c) for c in cores.values()) > 0.2 * len(points)


def test_the_embedded_cluster_has_the_programs_malloc_policy():
    """Its workers start with the allocator settings the program gives itself."""
    client, cluster = tiles._start_client(1, None, None)
    try:
        seen = client.run(lambda: {k: os.environ.get(k) for k in tiles.WORKER_MALLOC_POLICY})
    finally:
        client.close()
        cluster.close()
    expected = {k: os.environ.get(k, v) for k, v in tiles.WORKER_MALLOC_POLICY.items()}
    assert list(seen.values()) == [expected]


def test_an_open_sheet_across_many_tiles(client, tmp_path):
    rng = np.random.default_rng(3)
    side = 180
    grid = np.stack(np.meshgrid(np.linspace(0, 4, side), np.linspace(0, 4, side)), -1).reshape(-1, 2)
    grid = grid + rng.uniform(-0.3, 0.3, grid.shape) * 4 / side
    points = np.column_stack([grid, 0.3 * np.sin(grid[:, 0]) * np.sin(0.7 * grid[:, 1])])
    np.save(tmp_path / "sheet.npy", points)
    summary = tiles.process_tiles(tmp_path / "sheet.npy", tmp_path / "out", tile_points=2_100, client=client,
                                  merge=True, quiet=True, radii=("4s",))
    assert summary["tiles"] == 16
    merged = read_merged(tmp_path / "out", summary["layers"])
    normal = normals_of(merged, "r4s")
    on = np.isfinite(normal[:, 0])
    up = np.mean(normal[on, 2] > 0)
    assert max(up, 1 - up) >= 0.99
    assert summary["worst_seam_agreement"] >= 0.99
    # input normals decide, as in one run: all down here
    down = np.tile([0.0, 0.0, -1.0], (len(points), 1))
    np.save(tmp_path / "sheet_normals.npy", np.hstack([points, down]))
    summary = tiles.process_tiles(tmp_path / "sheet_normals.npy", tmp_path / "with_normals", tile_points=2_100,
                                  client=client, merge=True, quiet=True, radii=("4s",))
    assert summary["flipped"] == []
    normal = normals_of(read_merged(tmp_path / "with_normals", summary["layers"]), "r4s")
    assert np.mean(normal[np.isfinite(normal[:, 0]), 2] < 0) >= 0.99


def free_port():
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return s.getsockname()[1]


def tls_files(folder):
    """A throw-away certificate authority's file, and a certificate for
    127.0.0.1 that it signed and its key, which the scheduler, the workers and
    the client share."""
    openssl = "/usr/bin/openssl"
    if not os.access(openssl, os.X_OK):
        pytest.fail(f"the TLS test needs {openssl} (Debian's package openssl)")
    ca, ca_key, cert, key = (str(folder / name) for name in ("ca.pem", "ca.key", "cert.pem", "key.pem"))
    new_key = ["req", "-x509", "-newkey", "ec", "-pkeyopt", "ec_paramgen_curve:prime256v1", "-nodes", "-days", "1"]
    for signed in (["-keyout", ca_key, "-out", ca, "-subj", "/CN=throw-away CA"],
                   ["-keyout", key, "-out", cert, "-subj", "/CN=127.0.0.1", "-CA", ca, "-CAkey", ca_key,
                    "-addext", "subjectAltName=IP:127.0.0.1", "-addext", "basicConstraints=CA:FALSE"]):
        made = subprocess.run([openssl, *new_key, *signed], capture_output=True, text=True)
        assert made.returncode == 0, made.stderr
    return ca, cert, key


def test_scheduler_and_workers_on_localhost(tmp_path):
    """Debian's dask-scheduler and dask-worker as separate processes over TLS,
    and the command line with the client's TLS files and without them."""
    from distributed import Client
    from distributed.security import Security
    ca, cert, key = tls_files(tmp_path)
    tls = ["--tls-ca-file", ca, "--tls-cert", cert, "--tls-key", key]
    port = free_port()
    address = f"tls://127.0.0.1:{port}"
    services = []
    try:
        # the services' messages go to a file, shown if they do not start (a pipe nobody reads could fill)
        with open(tmp_path / "services.log", "w") as log:
            services.append(subprocess.Popen([sys.executable, "-m", "distributed.cli.dask_scheduler", "--host",
                                              "127.0.0.1", "--port", str(port), "--protocol", "tls",
                                              "--dashboard-address", ":0", *tls], stdout=subprocess.DEVNULL,
                                             stderr=log))
            for _ in range(2):
                services.append(subprocess.Popen([sys.executable, "-m", "distributed.cli.dask_worker", address,
                                                  "--nthreads", "1", "--host", "127.0.0.1", "--no-dashboard", *tls],
                                                 stdout=subprocess.DEVNULL, stderr=log))
        security = Security(tls_ca_file=ca, tls_client_cert=cert, tls_client_key=key, require_encryption=True)
        deadline = time.monotonic() + 60
        while True:
            try:
                with Client(address, security=security, timeout=5) as c:
                    c.wait_for_workers(2, timeout=30)
                break
            except Exception as e:
                if time.monotonic() > deadline or services[0].poll() is not None:
                    pytest.fail(f"dask-scheduler and 2 dask-workers on {address} did not start: {e!r}\n"
                                + (tmp_path / "services.log").read_text()[-4000:])
                time.sleep(0.5)
        points, _ = scene(12_000, seed=5)
        np.save(tmp_path / "small.npy", points)
        command = [sys.executable, "-m", "conformal_alpha_shapes.tiles", str(tmp_path / "small.npy"), "--output",
                   str(tmp_path / "out"), "--tile-points", "6000", "--scheduler", address, "--merge",
                   "--radius", "auto,4s"]
        refused = subprocess.run(command, capture_output=True, text=True, timeout=60)
        assert refused.returncode != 0
        assert f"the scheduler at {address} needs --tls-ca-file, --tls-cert and --tls-key" in refused.stderr, \
            refused.stderr
        run = subprocess.run(command + tls, capture_output=True, text=True, timeout=300)
        assert run.returncode == 0, run.stderr
        assert "tiles" in run.stderr and "worst tile" in run.stderr
        summary = tile_io.read_manifest(tmp_path / "out" / "manifest.json")
        merged = read_merged(tmp_path / "out", summary["names"])
        assert len(merged) == len(points)
    finally:
        for service in reversed(services):
            service.terminate()
        for service in services:
            try:
                service.wait(timeout=20)
            except subprocess.TimeoutExpired:
                service.kill()


def assert_same_output(path, expected):
    """The bytes of an undisturbed run: nothing a tile computes depends on its
    worker's heap or on the tiles it ran before (the manual, "Tiled
    Processing on Dask")."""
    with open(path, "rb") as f:
        data = f.read()
    assert len(data) == len(expected)
    assert data == expected, f"{sum(a != b for a, b in zip(data, expected))} bytes differ"


@pytest.fixture(scope="module")
def fault_input(client, tmp_path_factory):
    """A cloud in 4 tiles and its undisturbed tiled run (merged)."""
    folder = tmp_path_factory.mktemp("faults")
    points, _ = scene(24_000, seed=7)
    np.save(folder / "cloud.npy", points)
    tiles.process_tiles(folder / "cloud.npy", folder / "undisturbed", tile_points=6_000, client=client,
                        merge=True, quiet=True, radii=("auto", "4s"))
    with open(folder / "undisturbed" / "curvatures.ply", "rb") as f:
        return folder, f.read()


def test_a_killed_worker_is_replaced_and_the_output_is_the_same(fault_input, tmp_path):
    from distributed import Client, LocalCluster
    folder, expected = fault_input
    cluster = LocalCluster(n_workers=2, threads_per_worker=1, processes=True, host="127.0.0.1",
                           dashboard_address=None)
    killed = []
    try:
        with Client(cluster) as c:
            pids = list(c.run(os.getpid).values())

            def kill_mid_run():
                """Kills a worker once the first tile's closing values are written (tiles in flight)."""
                folder_of_tiles = tmp_path / "out" / "tiles"
                deadline = time.monotonic() + 120
                while time.monotonic() < deadline and not killed:
                    if folder_of_tiles.exists() and any(name.startswith("closing_")
                                                        for name in os.listdir(folder_of_tiles)):
                        os.kill(pids[0], signal.SIGKILL)
                        killed.append(pids[0])
                    time.sleep(0.02)
            killer = threading.Thread(target=kill_mid_run)
            killer.start()
            tiles.process_tiles(folder / "cloud.npy", tmp_path / "out", tile_points=6_000, client=c, merge=True,
                                quiet=True, radii=("auto", "4s"))
            killer.join()
    finally:
        cluster.close()
    assert killed, "no worker was killed during the run"
    assert_same_output(tmp_path / "out" / "curvatures.ply", expected)


def test_an_interrupted_run_restarts_from_its_parts(fault_input, tmp_path):
    folder, expected = fault_input
    command = [sys.executable, "-m", "conformal_alpha_shapes.tiles", str(folder / "cloud.npy"), "--output",
               str(tmp_path / "out"), "--tile-points", "6000", "--workers", "2", "--merge", "--radius", "auto,4s"]
    first = subprocess.Popen(command, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    manifest = tmp_path / "out" / "manifest.json"
    deadline = time.monotonic() + 180
    while time.monotonic() < deadline and first.poll() is None:
        if (tile_io.read_manifest(manifest) or {}).get("parts"):  # a finished part recorded
            break
        time.sleep(0.05)
    assert first.poll() is None, "the run ended before it could be interrupted"
    first.send_signal(signal.SIGINT)
    _, error = first.communicate(timeout=60)
    assert first.returncode == 130, error
    assert not (tmp_path / "out" / "curvatures.ply").exists()
    second = subprocess.run(command, capture_output=True, text=True, timeout=300)
    assert second.returncode == 0, second.stderr
    reused = [line for line in second.stderr.splitlines() if "parts reused" in line]
    assert reused and not reused[0].endswith(" 0 parts reused"), second.stderr
    assert_same_output(tmp_path / "out" / "curvatures.ply", expected)


def test_bad_input_fails_before_any_file_is_written(tmp_path):
    bad = tmp_path / "bad.xyz"
    bad.write_text("0 0 0\n1 0 0\n0 1 x\n0 0 1\n")
    with pytest.raises(tile_io.InputError, match=r"bad.xyz:3: not a number: 'x'"):
        tiles.process_tiles(bad, tmp_path / "out", workers=1)
    assert not (tmp_path / "out").exists()
    nan = tmp_path / "nan.xyz"
    nan.write_text("0 0 0\n1 0 0\n0 1 nan\n0 0 1\n1 1 1\n")
    with pytest.raises(tile_io.InputError, match=r"nan.xyz:3: coordinate is NaN or infinite: 'nan'"):
        tiles.process_tiles(nan, tmp_path / "out", workers=1)
    good = tmp_path / "good.xyz"
    good.write_text("0 0 0\n1 0 0\n0 1 0\n0 0 1\n")
    with pytest.raises(tiles.TileError, match=r"good.xyz: 4 points; a tiled run needs at least 25: .* 24 nearest"):
        tiles.process_tiles(good, tmp_path / "out", workers=1)
    assert not (tmp_path / "out").exists()
    with pytest.raises(tiles.TileError, match=r"scheduler: tls://127.0.0.1:1 needs security="):
        tiles.process_tiles(good, tmp_path / "out", scheduler="tls://127.0.0.1:1")
    run = subprocess.run([sys.executable, "-m", "conformal_alpha_shapes.tiles", str(good), "--output",
                          str(tmp_path / "out"), "--radius", "4q"], capture_output=True, text=True)
    assert run.returncode == 1
    assert "--radius: not a radius: '4q'" in run.stderr
    run = subprocess.run([sys.executable, "-m", "conformal_alpha_shapes.tiles", str(tmp_path / "missing.npy"),
                          "--output", str(tmp_path / "out")], capture_output=True, text=True)
    assert run.returncode == 1 and "missing.npy: no such file" in run.stderr
    assert not (tmp_path / "out").exists()


def test_bad_las_input_and_filters_fail_before_any_file_is_written(tmp_path):
    import las_spec
    good = tmp_path / "good.las"
    las_spec.write_las(good, 4, 6, las_spec.sample_fields(10, 6))
    data = good.read_bytes()
    (tmp_path / "scan.laz").write_bytes(data)
    (tmp_path / "short.las").write_bytes(data[:-1])
    cases = [(["scan.laz"], r"scan.laz: compressed LAS \(LAZ\) cannot be read without LASzip; decompress it"),
             (["short.las"], "short.las: the header announces 10 points of 30 bytes, the file holds 9"),
             (["good.las", "--classes", "2,x"], "--classes: not a LAS class from 0 to 255: 'x'"),
             (["good.las", "--classes", "256"], "--classes: not a LAS class from 0 to 255: '256'"),
             (["good.las", "--returns", "second"], "--returns: unknown returns 'second'")]
    for args, message in cases:
        run = subprocess.run([sys.executable, "-m", "conformal_alpha_shapes.tiles", str(tmp_path / args[0]),
                              "--output", str(tmp_path / "out"), *args[1:]], capture_output=True, text=True)
        assert run.returncode == 1 and re.search(message, run.stderr), (args, run.stderr)
    np.save(tmp_path / "points.npy", np.zeros((10, 3)))
    with pytest.raises(tile_io.InputError, match="points.npy: classes, drop_withheld and returns filter LAS input"):
        tiles.process_tiles(tmp_path / "points.npy", tmp_path / "out", workers=1, classes=[2])
    assert not (tmp_path / "out").exists()


def test_input_formats_read_in_chunks(tmp_path):
    points = np.random.default_rng(2).normal(size=(1000, 3))
    normals = points / np.linalg.norm(points, axis=1)[:, None]
    np.save(tmp_path / "p.npy", np.hstack([points, normals]))
    np.savetxt(tmp_path / "p.xyz", np.hstack([points, normals]), fmt="%.17g")
    records = np.empty(1000, [("x", "<f4"), ("y", "<f4"), ("z", "<f4"), ("nx", "<f4"), ("ny", "<f4"),
                              ("nz", "<f4"), ("quality", "u1")])
    for i, axis in enumerate("xyz"):
        records[axis], records["n" + axis] = points[:, i], normals[:, i]
    with open(tmp_path / "p.ply", "wb") as f:
        f.write(b"ply\nformat binary_little_endian 1.0\nelement vertex 1000\n" + b"".join(
            f"property {t} {n}\n".encode() for t, n in [("float", "x"), ("float", "y"), ("float", "z"),
                                                        ("float", "nx"), ("float", "ny"), ("float", "nz"),
                                                        ("uchar", "quality")]) + b"end_header\n")
        records.tofile(f)
    for name, tolerance in (("p.npy", 0), ("p.xyz", 0), ("p.ply", 1e-6)):
        cloud = tile_io.open_cloud(tmp_path / name)
        assert cloud.count == 1000 and cloud.has_normals
        chunks = list(cloud.chunks(300))
        assert [start for start, _, _ in chunks] == [0, 300, 600, 900]
        read = np.vstack([p for _, p, _ in chunks])
        assert np.allclose(read, points, rtol=0, atol=tolerance * 10)


def test_writes_are_atomic(tmp_path):
    target = tmp_path / "part.ply"

    def fails_halfway(temporary):
        with open(temporary, "wb") as f:
            f.write(b"half")
        raise OSError("disk full")
    with pytest.raises(OSError):
        tile_io.atomic_write(str(target), fails_halfway)
    assert not target.exists()
    assert os.listdir(tmp_path) == []
    tile_io.write_manifest(str(tmp_path / "manifest.json"), {"a": 1})
    assert tile_io.read_manifest(str(tmp_path / "manifest.json")) == {"a": 1}
    assert sorted(os.listdir(tmp_path)) == ["manifest.json"]


def test_a_las_input_is_read_in_chunks_and_gives_the_answer_of_its_points_as_ply(client, tmp_path, monkeypatch):
    """A LAS 1.2 file (point format 1, extra bytes, a GeoTIFF CRS) of a
    scene and noise of class 7: the run on class 2 reads it a range of
    records at a time and writes curvatures.las whose records, extra bytes
    and CRS are the input's and whose values are those of a run on the same
    points as binary PLY."""
    import las_spec
    from conformal_alpha_shapes import _native
    points, _ = scene(24_000, seed=3)
    rng = np.random.default_rng(5)
    noise = rng.uniform(-2, 2, (1500, 3))
    everything = np.vstack([points, noise])
    order = rng.permutation(len(everything))
    everything = everything[order]
    classification = np.where(order < len(points), 2, 7).astype(np.uint8)
    fields = las_spec.sample_fields(len(everything), 1)
    scale, offset = (1e-5, 1e-5, 1e-5), (0.0, 0.0, 0.0)
    for k, axis in enumerate("XYZ"):
        fields[axis] = np.round(everything[:, k] / scale[k]).astype(np.int32)
    fields["classification"] = classification
    fields["withheld"] = np.zeros(len(everything), bool)
    las_path = tmp_path / "scene.las"
    reflectance = rng.uniform(0, 1, len(everything)).astype(np.float32)
    las_spec.write_las(las_path, 2, 1, fields, scale=scale, offset=offset, crs="geotiff",
                       extra=[("reflectance", "<f4", reflectance)], undescribed=2)
    in_header, records, _, xyz = las_spec.read_las(las_path)
    kept = xyz[classification == 2]
    ply_path = tmp_path / "scene.ply"
    with open(ply_path, "wb") as f:
        f.write(f"ply\nformat binary_little_endian 1.0\nelement vertex {len(kept)}\nproperty double x\n"
                "property double y\nproperty double z\nend_header\n".encode())
        kept.astype("<f8").tofile(f)

    requested = []
    native_read = _native.read_las_chunk

    def recording(path, first, count, *rest):
        requested.append(count)
        return native_read(path, first, count, *rest)
    monkeypatch.setattr(_native, "read_las_chunk", recording)
    monkeypatch.setattr(tile_io, "LAS_CHUNK", 4096)
    monkeypatch.setattr(tile_io, "LAS_RECORDS_MADE", 1000)
    options = dict(tile_points=6_000, client=client, merge=True, quiet=True, radii=("auto", "4s"))
    summary = tiles.process_tiles(las_path, tmp_path / "out_las", classes=[2], las=True, **options)
    assert max(requested) <= 4096 and len(requested) > 3 * len(everything) // 4096
    assert summary["las"]["counts"] == {"read": len(everything), "classes": len(kept), "withheld": len(kept),
                                        "returns": len(kept)}
    assert (f"LAS 1.2, point format 1, {len(everything)} points; classes 2 kept {len(kept)}"
            in tiles.format_summary(summary))
    assert not (tmp_path / "out_las" / "curvatures.ply").exists()
    reference = tiles.process_tiles(ply_path, tmp_path / "out_ply", **options)
    assert reference["a"] == summary["a"] and reference["tiles"] == summary["tiles"] >= 4

    header, out_records, extra, out_xyz = las_spec.read_las(tmp_path / "out_las" / "curvatures.las")
    assert header["minor"] == 4 and header["format"] == 6 and header["count"] == len(kept)
    assert out_xyz.tobytes() == kept.tobytes()
    for axis in "XYZ":
        assert np.array_equal(out_records[axis], records[axis][classification == 2])
    assert np.array_equal(out_records["gps_time"], records["gps_time"][classification == 2])
    # the input's extra bytes and CRS carried
    assert np.array_equal(extra["reflectance"], reflectance[classification == 2])
    assert np.array_equal(extra["undescribed_extra_bytes"], records["undescribed_extra"][classification == 2])
    assert las_spec.crs_records(header) == las_spec.crs_records(in_header)
    merged = read_merged(tmp_path / "out_ply", summary["layers"])
    assert np.array_equal(extra["outlier"], merged["outlier"])
    for name in summary["layers"]:
        for value in ("H", "K", "nx", "d1z", "radius", "distance", "source"):
            assert np.array_equal(extra[f"{value}_{name}"], merged[f"{value}_{name}"], equal_nan=value != "source"), \
                (name, value)
