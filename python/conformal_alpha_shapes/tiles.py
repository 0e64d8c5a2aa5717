"""Tiled processing on Dask: the program's job on clouds larger than one
process holds, with the answer of one run (the manual, "Tiled Processing on
Dask").

    python3 -m conformal_alpha_shapes.tiles INPUT --output DIR [--tile-points N]
        [--workers W | --scheduler ADDRESS] [--merge] [the program's options]

or ``process_tiles(input, output, ...)`` from Python. The cloud is split into
spatial tiles of about ``tile_points`` core points, each read with a halo of
its neighbors' points; what one run decides for the whole cloud (spacing,
noise and denoising, the automatic scale) is decided once over all tiles and
given to each; each tile's core points go to a binary PLY part
(``DIR/parts/part_NNNNN.ply``), whose orientation agrees with its neighbors'
(a vote on the shared halo points, propagated over the tile graph).

This module is the driver: ``process_tiles`` and its phases, in the order the
data flows through the modules of the steps: ``tile_partition`` (the tiles'
files), ``tile_tasks`` (what the workers compute per tile), ``tile_orientation``
(the seams' votes and the parts turned), then the summary; ``tile_command``
reads the command line and ``tile_io`` the input and the run's files.
"""

import hashlib
import json
import math
import os
import shutil
import sys
import time

import numpy as np

from . import tile_command, tile_io, tile_orientation, tile_partition, tile_tasks

__all__ = ["process_tiles", "halo_spacings", "format_summary", "main", "TileError"]

# The automatic radius's largest candidate, in spacings (the manual, "Neighborhoods").
AUTOMATIC_RADIUS_SPACINGS = 22.6
# What the front and the local feature sizes reach beyond the fit's radius, in
# spacings: the poles and the front's facets of a core point's neighborhood
# must be those of one run (the manual measures that this is enough).
FRONT_REACH_SPACINGS = 8.0
# The share of the front's vertices the automatic scale covers (suggest_scale's default).
COVERAGE = 0.99
# Above this ratio of the last to the first value of the automatic scale's
# window, a few far-reaching closing values decide the scale and a tile's
# halo may not hold them: the summary says so (the manual, "Tiled Processing").
WIDE_TAIL = 2.5
# The format of a run's folder: a run kept by another format starts over.
RUN_FORMAT = 2
# The share of the workers' memory that the held shapes may take.
HELD_SHAPES_SHARE = 0.5
# estimate_noise()'s sample of the points (noise_sample_size in estimate_noise.h) and the neighbors of its fits
NOISE_SAMPLE = 100000
NOISE_NEIGHBORS = 24
# The points whose coordinates are summed at a time for the cloud's center
# (the sums' rounding is part of the answer).
CENTER_CHUNK = 1 << 20
# What the program asks of glibc's malloc (the manual, "Performance"):
# transparent huge pages where the kernel gives them on request, and one
# arena, so that a worker runs a tile as the program would.
WORKER_MALLOC_POLICY = {"GLIBC_TUNABLES": "glibc.malloc.hugetlb=1", "MALLOC_ARENA_MAX": "1"}
# The halo, in first spacings, of the outlier rule's 6 and the noise fits' 24
# nearest neighbors (a few spacings), before the spacing of one run is known.
NEAR_HALO_SPACINGS = 8.0


class TileError(ValueError):
    """Options a tiled run cannot take (the message names the option)."""


def halo_spacings(radii, rings, spacing):
    """The halo's width in spacings: the largest neighborhood radius of the
    layers (an absolute radius in spacings of the cloud, a ring of ``k`` as
    ``1.5 k`` spacings, "auto" its largest candidate) plus the front's reach."""
    largest = 0.0
    for item in radii:
        text = str(item)
        if text == "auto":
            largest = max(largest, AUTOMATIC_RADIUS_SPACINGS)
        elif text.endswith("s"):
            largest = max(largest, float(text[:-1]))
        else:
            largest = max(largest, float(text) / spacing)
    for ring in rings:
        largest = max(largest, 1.5 * int(ring))
    return largest + FRONT_REACH_SPACINGS


class _Progress:
    """Tiles done of total, points per second and time left, on one terminal line."""

    def __init__(self, stage, total, points, quiet):
        self.stage, self.total, self.points, self.quiet = stage, total, points, quiet
        self.done, self.done_points, self.started = 0, 0, time.monotonic()

    def advance(self, points):
        self.done += 1
        self.done_points += points
        if self.quiet:
            return
        elapsed = max(time.monotonic() - self.started, 1e-9)
        rate = self.done_points / elapsed
        left = (self.points - self.done_points) / rate if rate > 0 else float("inf")
        end = "\n" if self.done == self.total else ""
        print(f"\r{self.stage}: tiles {self.done}/{self.total}, {rate:,.0f} points/s, "
              f"{left:.0f} s left   ", end=end, file=sys.stderr, flush=True)


def _run_tasks(client, function, arguments, stage, points, quiet, on_result):
    """Runs ``function(*args)`` for each ``(key, args)`` on the cluster (a lost
    worker's tasks are retried), calling ``on_result(key, value)`` as each ends."""
    from distributed import as_completed
    progress = _Progress(stage, len(arguments), points, quiet)
    futures = {client.submit(function, *args, key=f"{stage}-{key}-{os.urandom(4).hex()}", retries=3,
                             pure=False): key for key, args in arguments}
    for future in as_completed(futures):
        value = future.result()
        on_result(futures[future], value)
        progress.advance(value.get("core", 0) if isinstance(value, dict) else 0)
        future.release()


def _ordered_keys(values):
    """Integers in the order of the doubles ``values``."""
    bits = np.asarray(values, dtype=np.float64).view(np.int64)
    return bits ^ ((bits >> 63) & np.int64(0x7FFFFFFFFFFFFFFF))


def _key_value(key):
    """The double whose ordered key is ``key`` (the map is its own inverse)."""
    return float(_ordered_keys(np.array([key], dtype=np.int64).view(np.float64)).view(np.float64)[0])


def _sorted_values(paths):
    """The values of the sorted ``.npy`` files ``paths`` that hold any, memory-mapped."""
    return [a for a in (np.load(path, mmap_mode="r") for path in paths) if len(a)]


def _kth_smallest(arrays, k):
    """The ``k``-th smallest (from 0) of the values of sorted arrays pooled,
    exactly: a bisection over the doubles' bit patterns, counting with a
    binary search in each array."""
    lo = int(min(_ordered_keys(a[:1])[0] for a in arrays))
    hi = int(max(_ordered_keys(a[-1:])[0] for a in arrays))
    while lo < hi:  # the smallest value with more than k values at or below it
        middle = (lo + hi) // 2
        value = _key_value(middle)
        if sum(int(np.searchsorted(a, value, side="right")) for a in arrays) > k:
            hi = middle
        else:
            lo = middle + 1
    return _key_value(lo)


def _window(n, coverage):
    """The ranks of ``scale_of_closing_values()``'s window of ``n`` values: first, last (excluded)."""
    first = min(n - 1, int(coverage * n))
    return first, max(first + 1, min(n, int((coverage + 0.9 * (1 - coverage)) * n)))


def _tail_spread(arrays, coverage):
    """The last value of the window of the sorted ``arrays`` pooled over its
    first (None without values or when the first is 0)."""
    n = sum(len(a) for a in arrays)
    if n == 0:
        return None
    first, last = _window(n, coverage)
    start = _kth_smallest(arrays, first)
    return _kth_smallest(arrays, last - 1) / start if start > 0 else None


def _scale_of_closing_values(arrays, coverage):
    """``scale_of_closing_values()`` of the C++ library over the values of
    the sorted ``arrays`` pooled, to the bit: the mean, summed in increasing
    order, of the pooled values of ranks ``coverage n`` up to, not including,
    ``(coverage + 0.9 (1 - coverage)) n``; only the values from the first of
    them up are read."""
    n = sum(len(a) for a in arrays)
    if n == 0:
        return float("inf")
    first, last = _window(n, coverage)
    start = _kth_smallest(arrays, first)
    below = sum(int(np.searchsorted(a, start, side="left")) for a in arrays)
    tail = np.sort(np.concatenate([a[int(np.searchsorted(a, start, side="left")):] for a in arrays]))
    return float(np.cumsum(tail[first - below:last - below])[-1] / (last - first))


def _arguments_hash(input_path, options):
    """What makes two runs the same: the input file (path, size, time), the
    options and the format of what the run keeps (``RUN_FORMAT``)."""
    stat = os.stat(input_path)
    text = json.dumps([os.path.abspath(input_path), stat.st_size, stat.st_mtime_ns, options, RUN_FORMAT],
                      sort_keys=True)
    return hashlib.sha256(text.encode()).hexdigest()


def _check_options(options):
    """The program's checks of the options (its messages, with the Python
    keywords) and the limits of tiled runs, before any file is written."""
    from . import multiscale_curvatures
    for item in options["scales"]:
        if str(item).endswith("%"):
            raise TileError(f"scales: a quantile scale ('{item}') is a quantile over one shape's facets; "
                            "tiled runs take 'auto' and values")
    if options["extraction"] != "front" and "auto" in [str(x) for x in options["scales"]]:
        raise TileError("scales: the automatic scale of a tiled run needs extraction 'front'")
    tetrahedron = np.array([[0, 0, 0], [1, 0, 0], [0, 1, 0], [0, 0, 1.0]])
    multiscale_curvatures(tetrahedron, scales=options["scales"], radii=options["radii"], rings=options["rings"],
                          estimator=options["estimator"], denoise=options["denoise"],
                          denoise_neighbors=options["denoise_neighbors"], extraction=options["extraction"],
                          spacing=1.0, noise=0.0, threads=1)
    if options["tile_points"] < 1000:
        raise TileError(f"tile_points: at least 1000 points per tile, got {options['tile_points']}")


def _start_client(workers, scheduler, security):
    """A client of the cluster at ``scheduler``, or of a new LocalCluster of
    ``workers`` processes on 127.0.0.1 (no dashboard), with the machine's
    memory shared among them."""
    from distributed import Client, LocalCluster
    if scheduler:
        return Client(scheduler, security=security, timeout=30), None
    import dask
    workers = workers or max(1, os.cpu_count() or 1)
    memory = os.sysconf("SC_PAGE_SIZE") * os.sysconf("SC_PHYS_PAGES")
    # the program's allocator policy, read by glibc when a worker process
    # starts (the environment's own values win)
    environ = dict(dask.config.get("distributed.nanny.pre-spawn-environ"), **WORKER_MALLOC_POLICY)
    with dask.config.set({"distributed.nanny.pre-spawn-environ": environ}):
        cluster = LocalCluster(n_workers=workers, threads_per_worker=1, processes=True, host="127.0.0.1",
                               dashboard_address=None, memory_limit=memory // workers)
    return Client(cluster), cluster


def process_tiles(input, output, *, tile_points=1_000_000, workers=None, scheduler=None, security=None,
                  client=None, merge=False, scales=("auto",), radii=("auto", "2s", "4s", "8s", "16s"),
                  rings=(), estimator="quadric", denoise="auto", denoise_neighbors=None, extraction="front",
                  halo=None, threads=1, quiet=False, classes=None, drop_withheld=False, returns="all", las=False):
    """The program's job on a cloud split into tiles, on a Dask cluster.

    Parameters:
        input: a binary PLY (float or double x y z, optional nx ny nz), a
            ``.npy`` of shape (N, 3) or (N, 6) (memory-mapped), a ``.xyz`` or
            a ``.las`` (LAS 1.0 to 1.4, read a range of records at a time).
        output: the folder of the run: ``parts/part_NNNNN.ply`` (each tile's
            core points, the fields of the program's ``curvatures.ply`` plus
            ``input_index``), ``manifest.json``, ``summary.json`` (what this
            returns), ``tiles/`` (the tiles' points and intermediate values)
            and with ``merge`` ``curvatures.ply`` in input order.
            Every worker must read and write it (local disk or a shared file system).
        tile_points: the target number of core points per tile.
        workers: worker processes of the embedded LocalCluster (default: one per core).
        scheduler: the address of an existing Dask scheduler instead
            ("tls://host:8786"), with ``security`` (a
            ``distributed.security.Security``) for TLS.
        client: an existing ``distributed.Client`` instead of either.
        merge: also write ``curvatures.ply``, the program's file.
        las: with ``merge``, write ``curvatures.las`` instead (LAS 1.4, as
            ``Result.write_las``: a LAS input's records, fields, extra bytes
            and CRS records, the values as named extra bytes), a chunk at a
            time; the parts stay binary PLY.
        classes, drop_withheld, returns: for a LAS input, the filters of
            ``read_point_cloud``: the run is on the points they keep (the
            parts' ``input_index`` counts those).
        scales, radii, rings, estimator, denoise, denoise_neighbors,
        extraction: as ``multiscale_curvatures`` (scales: "auto" and values).
        halo: the halo's width in spacings (default ``halo_spacings()``).
        threads: threads per tile (TBB); the cluster runs one tile per worker thread.
        quiet: no progress and no summary on the terminal.

    Returns:
        The summary (a dict): tiles, points, spacing, noise, denoised, a per
        scale, a_tail_spread (the last value of the automatic scale's window
        of closing values over its first; the text summary warns above
        2.5), halo, the seams' agreement, the worst tile, workers' peak
        memory.

    Raises:
        tile_io.InputError: bad input (file and line), before any file is written.
        TileError: fewer than 25 points (before any file is written), or
            points whose sample spacing cannot be estimated.
        ValueError, TypeError: bad options, as ``multiscale_curvatures``.
    """
    options = {"scales": [str(x) for x in ((scales,) if isinstance(scales, (str, float, int)) else scales)],
               "radii": [str(x) for x in ((radii,) if isinstance(radii, (str, float, int)) else radii)],
               "rings": [int(x) for x in ((rings,) if isinstance(rings, int) else rings)],
               "estimator": estimator, "denoise": {True: "on", False: "off"}.get(denoise, denoise),
               "denoise_neighbors": denoise_neighbors, "extraction": extraction,
               "tile_points": int(tile_points), "halo": halo}
    las_filter = {"classes": [int(c) for c in ((classes,) if isinstance(classes, int) else (classes or ()))],
                  "drop_withheld": bool(drop_withheld), "returns": returns}
    if las_filter != {"classes": [], "drop_withheld": False, "returns": "all"}:
        options["las_filter"] = las_filter
    _check_options(options)
    if client is None and str(scheduler or "").startswith("tls://") and security is None:
        # else Dask fails with a TypeError about an ssl_context
        raise TileError(f"scheduler: {scheduler} needs security=distributed.security.Security(tls_ca_file=..., "
                        "tls_client_cert=..., tls_client_key=...)")
    input = os.fspath(input)
    cloud = tile_io.open_cloud(input, las_filter)
    if cloud.count < 25:
        raise TileError(f"{input}: {cloud.count} points; a tiled run needs at least 25: the sample spacing, which "
                        "sets the tiles' halos and radii, is estimated from each point's 24 nearest neighbors")
    started = time.monotonic()
    os.makedirs(os.path.join(output, "tiles"), exist_ok=True)
    os.makedirs(os.path.join(output, "parts"), exist_ok=True)
    manifest_path = os.path.join(output, "manifest.json")
    key = _arguments_hash(input, options)
    manifest = tile_io.read_manifest(manifest_path)
    if not manifest or manifest.get("arguments_hash") != key:
        for folder in ("tiles", "parts"):
            shutil.rmtree(os.path.join(output, folder))
            os.makedirs(os.path.join(output, folder))
        manifest = {"arguments_hash": key, "input": os.path.abspath(input), "options": options,
                    "count": cloud.count, "parts": {}}
    def save():
        tile_io.write_manifest(manifest_path, manifest)
    started_client = client is None
    cluster = None
    if started_client:
        client, cluster = _start_client(workers, scheduler, security)
    try:
        summary = _run(client, cloud, output, options, manifest, save, threads, quiet)
    finally:
        if started_client:
            client.close()
        if cluster is not None:
            cluster.close()
    if merge:
        names = manifest["names"]
        merged = os.path.join(output, "tiles", "merged.ply") if las else os.path.join(output, "curvatures.ply")
        tile_io.merge_parts(merged, [tile_partition.part_path(output, t) for t in range(manifest["tiles"])], names,
                            manifest["descriptions"], cloud.count)
        if las:
            tile_io.merge_parts_las(os.path.join(output, "curvatures.las"), merged, names, cloud)
            os.unlink(merged)
    if cloud.las is not None:
        summary["las"] = {"version": cloud.las["version"], "point_format": cloud.las["point_format"],
                          "filter": cloud.las_filter, "counts": cloud.las_counts}
    summary["seconds"] = time.monotonic() - started
    tile_io.write_manifest(os.path.join(output, "summary.json"), summary)
    if not quiet:
        print(format_summary(summary), file=sys.stderr)
    return summary


def _partition(cloud, output, options, manifest, save, client, quiet):
    """The tiles' cores; near halos (a few spacings, from a first spacing
    pooled over the tiles) for the spacing and noise of one run; then the
    halos of the rule in that spacing (all in the manifest)."""
    has_normals = cloud.has_normals
    if "tree" not in manifest:
        stride = max(1, cloud.count // 1_000_000)
        tiles = max(1, math.ceil(cloud.count / options["tile_points"]))
        # the sample (up to 2 million points) goes to a file and is cut on a
        # worker, so that the driver holds one chunk of the cloud at a time
        sample_path = os.path.join(output, "tiles", "sample.f8")
        with open(sample_path, "wb") as f:
            for start, p, _ in cloud.chunks(tile_partition.CHUNK):
                p[(-start) % stride::stride].tofile(f)
        tree = client.submit(_sample_tree, sample_path, stride, tiles, options, retries=3, pure=False).result()
        os.unlink(sample_path)
        core = tile_partition.write_tile_files(cloud, tree, tiles, output, 0.0, "core")
        total = np.zeros(3)
        # chunks of this size, whose sums' rounding is part of the center
        for _, p, _ in cloud.chunks(CENTER_CHUNK):
            total += p.sum(axis=0)
        manifest.update(tree=tree, tiles=tiles, core=core, center=(total / cloud.count).tolist())
        save()
    tiles, tree = manifest["tiles"], manifest["tree"]
    if "first_spacing" not in manifest:
        estimates = {}
        _run_tasks(client, tile_tasks.tile_noise, [(t, (output, t, has_normals)) for t in range(tiles)],
                   "first spacing", cloud.count, quiet, lambda t, value: estimates.__setitem__(t, value))
        counts = np.array([estimates[t]["core"] for t in range(tiles)], dtype=np.float64)
        first_spacing = float(np.average([estimates[t]["spacing"] for t in range(tiles)], weights=counts))
        tile_partition.write_tile_files(cloud, tree, tiles, output, NEAR_HALO_SPACINGS * first_spacing, "halo")
        manifest.update(first_spacing=first_spacing)
        save()
    if "spacing" not in manifest:
        manifest.update(_global_noise(client, cloud, output, tiles, quiet))
        calls = manifest["noise"] > 0.02 and manifest["noise_24"] <= 1.3 * manifest["noise"]
        manifest["denoise"] = options["denoise"] if options["denoise"] != "auto" else ("on" if calls else "off")
        save()
    if "halo_spacings" not in manifest:
        halo = _halo(options, manifest["spacing"])
        tile_partition.write_tile_files(cloud, tree, tiles, output, halo * manifest["spacing"], "halo")
        manifest.update(halo_spacings=halo)
        save()


def _sample_tree(path, stride, tiles, options):
    """The partition's tree of cuts over the sample in the file ``path``
    (every ``stride``-th point, as float64 triples): a worker's task."""
    sample = np.fromfile(path, dtype=np.float64).reshape(-1, 3)
    band = _sample_halo(sample, stride, options) if tiles > 1 else 0.0
    return tile_partition.split(sample, tiles, 0, band)


def _sample_halo(sample, stride, options):
    """The halo's width as the partition foresees it: the rule's width in the
    spacing of the points, from the sample's spacing (every ``stride``-th
    point of a surface: ``sqrt(stride)`` times the points')."""
    from . import _unchecked_noise_estimate
    spacing = _unchecked_noise_estimate(sample).spacing / math.sqrt(stride)
    return _halo(options, spacing) * spacing


def _halo(options, spacing):
    """The halo's width in spacings: the ``halo`` option, or the rule's."""
    return options["halo"] or halo_spacings(options["radii"], options["rings"], spacing)


def _global_noise(client, cloud, output, tiles, quiet):
    """The noise estimate of one run, from the tiles: the outliers left out,
    the working frame (the kept points' per-axis median and robust size, by
    exact selection over the tiles), the sample of the points with the
    smallest order-free keys in that frame, and ``estimate_noise()`` on that
    sample with the neighbors of its fits, which it gives as on the whole cloud."""
    has_normals = cloud.has_normals
    kept, outliers = {}, []

    def outliers_done(t, value):
        kept[t] = value["kept"]
        outliers.extend(value["outliers"])
    _run_tasks(client, tile_tasks.tile_outliers, [(t, (output, t, has_normals)) for t in range(tiles)],
               "outliers", cloud.count, quiet, outliers_done)
    n = sum(kept.values())
    center = [_kth_smallest(_sorted_values([tile_partition.tile_path(output, t, f"axis{axis}.npy")
                                            for t in range(tiles)]), n // 2)
              for axis in range(3)]
    _run_tasks(client, tile_tasks.tile_half_radii, [(t, (output, t, has_normals, center)) for t in range(tiles)],
               "working frame", cloud.count, True, lambda t, value: None)
    radii = _sorted_values([tile_partition.tile_path(output, t, "radius.npy") for t in range(tiles)])
    h = _kth_smallest(radii, n // 2)
    if not h > 0:
        h = max(float(a[-1]) for a in radii)
    exponent = int(np.frexp(h)[1]) + 1 if h > 0 else 0  # ilogb(h) + 2
    # the smallest keys of the tiles' samples merged as they come (the keys
    # are distinct), so that the driver holds two samples, not one per tile
    pool = [np.empty(0, np.int64), np.empty((0, 3)), np.empty(0, np.int64)]

    def sampled(t, value):
        index = np.concatenate([pool[0], value[0]])
        q = np.concatenate([pool[1], value[1]])
        owner = np.concatenate([pool[2], np.full(len(value[0]), t)])
        rows = tile_tasks.smallest_keys(index, q, NOISE_SAMPLE)
        pool[:] = index[rows], q[rows], owner[rows]
    _run_tasks(client, tile_tasks.tile_noise_sample,
               [(t, (output, t, has_normals, center, exponent, NOISE_SAMPLE)) for t in range(tiles)],
               "noise sample", cloud.count, True, sampled)
    index, _, owner = pool
    futures = [client.submit(tile_tasks.tile_noise_neighbors, output, t, has_normals, center, exponent,
                             np.sort(index[owner == t]), NOISE_NEIGHBORS, retries=3, pure=False)
               for t in range(tiles) if np.any(owner == t)]
    # pooled on a worker: the neighbors number up to 24 times the sample
    estimate = client.submit(tile_tasks.pooled_noise_estimate, futures, retries=3, pure=False).result()
    if not estimate.spacing > 0:
        raise TileError(f"{cloud.path}: {cloud.count} points; the sample spacing, which sets the tiles' halos and "
                        "radii, is estimated from each point's 24 nearest neighbors and could not be: a tiled "
                        "run needs at least 25 points, not all coincident or on a line")
    return {"spacing": float(np.ldexp(estimate.spacing, exponent)), "noise": float(estimate),
            "noise_24": estimate.noise_24, "outliers": len(outliers), "working_frame": [center, exponent]}


def _automatic_scale(client, cloud, output, manifest, save, job, shapes, quiet):
    """The automatic scale of the whole cloud: the scale of the core points'
    local closing values of all tiles pooled (one run's rule, the same mean
    over the same window of the tail)."""
    if "a" in manifest:
        return manifest["a"]
    tiles = manifest["tiles"]
    counts, stats = {}, {}

    def done(t, value):
        counts[t] = value["count"]
        stats[t] = value
    _run_tasks(client, tile_tasks.tile_closing,
               [(t, (output, t, cloud.has_normals, job, shapes.get(t))) for t in range(tiles)],
               "closing values", cloud.count, quiet, done)
    closing = _sorted_values([os.path.join(output, "tiles", f"closing_{t:05d}.npy") for t in range(tiles)])
    a = _scale_of_closing_values(closing, COVERAGE)
    manifest.update(a=a, a_tail_spread=_tail_spread(closing, COVERAGE),
                    closing_stats={str(t): {"seconds": v["seconds"], "memory": v["memory"]} for t, v in stats.items()})
    save()
    return a


def _part_is_finished(output, tile, entry):
    """Whether a part on disk is the one the manifest records (size and SHA-256)."""
    path = tile_partition.part_path(output, tile)
    return (entry is not None and os.path.exists(path) and os.path.getsize(path) == entry["size"]
            and tile_io.file_digest(path) == entry["sha256"])


def _shapes_fit(client, output, manifest, has_normals):
    """Whether all tiles' shapes fit in the workers' memory at once (a share
    of their limits; a worker without a limit makes it unknown: no)."""
    limits = [worker.get("memory_limit") or 0 for worker in client.scheduler_info()["workers"].values()]
    if not limits or min(limits) <= 0:
        return False
    record = tile_partition.record_dtype(has_normals).itemsize
    points = sum(manifest["core"]) + sum(os.path.getsize(tile_partition.tile_path(output, t, "halo")) // record
                                         for t in range(manifest["tiles"]))
    return points * tile_tasks.SHAPE_BYTES_PER_POINT <= HELD_SHAPES_SHARE * sum(limits)


def _run(client, cloud, output, options, manifest, save, threads, quiet):
    _partition(cloud, output, options, manifest, save, client, quiet)
    tiles = manifest["tiles"]
    job = dict(options, spacing=manifest["spacing"], noise=manifest["noise"], denoise=manifest["denoise"],
               halo_spacings=manifest["halo_spacings"], threads=threads)
    parts = manifest["parts"]
    todo = [t for t in range(tiles) if not _part_is_finished(output, t, parts.get(str(t)))]
    reused = tiles - len(todo)
    closing = "auto" in options["scales"] and "a" not in manifest
    keep = closing and todo and _shapes_fit(client, output, manifest, cloud.has_normals)
    # futures of the shapes on their workers, from the closing values to the curvature
    shapes = {t: client.submit(tile_tasks.tile_shape, output, t, cloud.has_normals, job, retries=3, pure=False,
                               key=f"shape-{t}-{os.urandom(4).hex()}") for t in range(tiles)} if keep else {}
    manifest["shapes"] = "kept" if keep else ("rebuilt" if closing and todo else "built once")
    if "auto" in options["scales"]:
        a = _automatic_scale(client, cloud, output, manifest, save, job, shapes, quiet)
        job["tile_scales"] = [repr(a) if x == "auto" else x for x in options["scales"]]
    else:
        job["tile_scales"] = list(options["scales"])
    for t in [t for t in shapes if t not in todo]:
        shapes.pop(t).release()

    def done(t, value):
        value = dict(value, flips=[[] for _ in options["scales"]])
        parts[str(t)] = value
        manifest.update(names=value["names"], descriptions=value["descriptions"])
        save()
    _run_tasks(client, tile_tasks.tile_curvatures,
               [(t, (output, t, cloud.has_normals, job, manifest["center"], manifest["tree"], shapes.get(t)))
                for t in todo],
               "curvature", sum(manifest["core"][t] for t in todo), quiet, done)
    for future in shapes.values():
        future.release()
    names = parts["0"]["names"]
    per_scale = len(names) // len(options["scales"])
    first_names = [names[s * per_scale] for s in range(len(options["scales"]))]
    scale_layers = [names[s * per_scale:(s + 1) * per_scale] for s in range(len(options["scales"]))]
    states = [parts[str(t)]["flips"] for t in range(tiles)]
    votes = {}
    _run_tasks(client, tile_orientation.tile_votes,
               [(t, (output, t, names, first_names, states)) for t in range(tiles)],
               "seams", 0, True, votes.__setitem__)
    flips = tile_orientation.orient(votes, [parts[str(t)] for t in range(tiles)], len(first_names),
                                    cloud.has_normals)
    changes = []
    for t in range(tiles):
        turns = {s: sorted(set(flips[t][s]) ^ set(states[t][s])) for s in range(len(first_names))}
        turns = {s: objects for s, objects in turns.items() if objects}
        if turns:
            changes.append((t, turns))

    def flipped(t, value):
        parts[str(t)].update(value, flips=flips[t])
        save()
    _run_tasks(client, tile_orientation.tile_flip,
               [(t, (output, t, names, scale_layers, turns)) for t, turns in changes],
               "orientation", 0, True, flipped)
    return _summary(manifest, votes, flips, reused, cloud, first_names)


def _summary(manifest, votes, flips, reused, cloud, first_names):
    """The figures of the run: decisions, seams (after orientation), worst tile, memory."""
    parts = manifest["parts"]
    seams = {}
    for i, tile_votes in votes.items():
        for s, mine, j, theirs, agree, disagree in tile_votes:
            if (mine in flips[i][s]) != (theirs in flips[j][s]):
                agree, disagree = disagree, agree
            entry = seams.setdefault((min(i, j), max(i, j)), [[0, 0] for _ in first_names])
            entry[s][0] += agree
            entry[s][1] += disagree
    seam_list = [{"tiles": list(pair), "points": [a + d for a, d in counts],
                  "agreement": [a / (a + d) if a + d else None for a, d in counts]}
                 for pair, counts in sorted(seams.items())]
    memory = {}
    for entry in list(parts.values()) + list(manifest.get("closing_stats", {}).values()):
        size, pid = entry["memory"]
        memory[pid] = max(memory.get(pid, 0), size)
    worst = max(parts, key=lambda t: parts[t]["seconds"])
    agreements = [x for seam in seam_list for x, n in zip(seam["agreement"], seam["points"])
                  if x is not None and n >= tile_orientation.MINIMUM_SEAM_POINTS]
    return {"tiles": manifest["tiles"], "points": cloud.count, "spacing": manifest["spacing"],
            "noise": manifest["noise"], "denoised": manifest["denoise"] == "on",
            "a": parts["0"]["a"], "a_tail_spread": manifest.get("a_tail_spread"),
            "halo_spacings": manifest["halo_spacings"],
            "layers": parts["0"]["names"], "seams": seam_list,
            "worst_seam_agreement": min(agreements) if agreements else None,
            "worst_tile": {"tile": int(worst), "seconds": parts[worst]["seconds"],
                           "points": parts[worst]["points"], "core": parts[worst]["core"]},
            "tile_points_with_halo": sum(parts[t]["points"] for t in parts),
            "reused_parts": reused,
            "flipped": [[t, s, objects] for t, row in enumerate(flips) for s, objects in enumerate(row) if objects],
            "worker_peak_memory": {str(pid): size for pid, size in memory.items()},
            "shapes": manifest["shapes"],
            "objects_without_normals": len(tile_orientation.not_following_normals(
                [parts[str(t)] for t in range(manifest["tiles"])], 0)) if cloud.has_normals else None}


_SHAPES_TEXT = {
    "kept": "each tile's shape kept on its worker from the closing values to the curvature",
    "rebuilt": "each tile's shape built twice (closing values, curvature): the workers' memory cannot hold all",
    "built once": "each tile's shape built once"}


def format_summary(summary):
    """The summary as the program prints its own: a few lines of text."""
    seams = [s for s in summary["seams"] if max(s["points"]) >= tile_orientation.MINIMUM_SEAM_POINTS]
    las = summary.get("las")
    lines = []
    if las:
        kept = [f"classes {','.join(str(c) for c in las['filter']['classes'])} kept {las['counts']['classes']}"]\
            if las["filter"]["classes"] else []
        kept += [f"without withheld points kept {las['counts']['withheld']}"] if las["filter"]["drop_withheld"] else []
        kept += [f"{las['filter']['returns']} returns kept {las['counts']['returns']}"] \
            if las["filter"]["returns"] != "all" else []
        lines.append("; ".join([f"LAS {las['version']}, point format {las['point_format']}, "
                                f"{las['counts']['read']} points"] + kept))
    lines += [f"{summary['points']} points in {summary['tiles']} tiles "
             f"({summary['tile_points_with_halo']} with halos of {summary['halo_spacings']:.1f} spacings), "
             f"{summary['reused_parts']} parts reused",
             f"noise: {summary['noise']:.3g} x spacing (spacing {summary['spacing']:.4g}); "
             f"{'smoothed' if summary['denoised'] else 'no smoothing'}",
             "scales: " + ", ".join(f"a = {a:.4g}" for a in summary["a"]),
             *([f"automatic scale: the closing values of its window differ by a factor of "
                f"{summary['a_tail_spread']:.3g} (above {WIDE_TAIL}): a few far-reaching values decide it, and a "
                "tile's halo may not hold them, so it may not be one run's (--alpha gives a scale, a wider --halo "
                "may help)"] if (summary.get("a_tail_spread") or 0) > WIDE_TAIL else []),
             _SHAPES_TEXT[summary["shapes"]],
             *([f"input normals: {summary['objects_without_normals']} object(s) of the tiles point about as often "
                "to one side as to the other (unoriented normals?); oriented as without normals"]
               if summary.get("objects_without_normals") else []),
             f"seams: {len(seams)}, worst agreement "
             + (f"{100 * summary['worst_seam_agreement']:.2f}%" if summary["worst_seam_agreement"] is not None
                else "none"),
             f"worst tile: {summary['worst_tile']['tile']}, {summary['worst_tile']['points']} points, "
             f"{summary['worst_tile']['seconds']:.1f} s",
             "workers' peak memory: " + ", ".join(f"{size / 2**30:.2f} GiB"
                                                  for size in summary["worker_peak_memory"].values()),
             f"{summary.get('seconds', 0):.1f} s"]
    return "\n".join(lines)


def main(argv=None):
    """The command line; returns the exit status (1 with one line on stderr on failure)."""
    args = tile_command.arguments(argv)
    security = tile_command.security(args)
    try:
        process_tiles(args.input, args.output, security=security, **tile_command.options(args))
    except KeyboardInterrupt:
        print("conformal_alpha_shapes.tiles: interrupted; run again with the same arguments to finish",
              file=sys.stderr)
        return 130
    except (ValueError, TypeError, OSError) as e:
        print(f"conformal_alpha_shapes.tiles: {tile_command.flag_message(str(e))}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
