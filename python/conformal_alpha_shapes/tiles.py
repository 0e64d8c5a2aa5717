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
"""

import argparse
import hashlib
import json
import math
import os
import resource
import shutil
import sys
import time

import numpy as np

from . import tile_io

__all__ = ["process_tiles", "halo_spacings", "format_summary", "main"]

# The automatic radius's largest candidate, in spacings (the manual, "Neighborhoods").
AUTOMATIC_RADIUS_SPACINGS = 22.6
# What the front and the local feature sizes reach beyond the fit's radius, in
# spacings: the poles and the front's facets of a core point's neighborhood
# must be those of one run (the manual measures that this is enough).
FRONT_REACH_SPACINGS = 8.0
# The share of the front's vertices the automatic scale covers (suggest_scale's default).
COVERAGE = 0.99
# What a tile's shape held between phases weighs per point with halo, and
# the share of the workers' memory that the held shapes may take (the manual,
# "Tiled Processing on Dask", measures the weight).
SHAPE_BYTES_PER_POINT = 2300
HELD_SHAPES_SHARE = 0.5
# The cells, in spacings, whose touching joins the points of one object.
COMPONENT_CELL_SPACINGS = 3.0
# Shared points below which a seam does not vote (a corner touching a halo).
MINIMUM_SEAM_POINTS = 20
# Points the driver reads at a time.
CHUNK = 1 << 20
# estimate_noise()'s sample of the points and the neighbors of its fits
NOISE_SAMPLE = 2000
NOISE_NEIGHBORS = 24
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


# --- the partition -----------------------------------------------------------

def _split(sample, tiles, first):
    """A tree of cuts over ``sample``: a leaf is a tile number, a node
    ``[axis, cut, left, right]`` sends points below ``cut`` left; the median
    split on the longest axis, at the share of the tiles on each side."""
    if tiles == 1:
        return first
    extent = sample.max(axis=0) - sample.min(axis=0)
    axis = int(np.argmax(extent))
    left = tiles // 2
    cut = float(np.quantile(sample[:, axis], left / tiles))
    below = sample[:, axis] < cut
    return [axis, cut, _split(sample[below], left, first), _split(sample[~below], tiles - left, first + left)]


def _assign(tree, points, margin, index=None, out=None):
    """Per tile, the rows of ``points`` within ``margin`` of its box (0: its core)."""
    if out is None:
        out, index = {}, np.arange(len(points))
    if not isinstance(tree, list):
        out[tree] = index
        return out
    axis, cut, left, right = tree
    values = points[index, axis]
    _assign(left, points, margin, index[values < cut + margin], out)
    _assign(right, points, margin, index[values >= cut - margin], out)
    return out


def _owner(tree, points):
    """The tile whose core holds each point."""
    owner = np.empty(len(points), dtype=np.int32)
    for tile, rows in _assign(tree, points, 0.0).items():
        owner[rows] = tile
    return owner


def _components(points, size):
    """Labels (0, 1, ...) of the groups of points joined through cells of
    side ``size`` that touch (faces, edges or corners): the separate objects
    of a tile, which one run orients each on its own."""
    cell = np.floor((points - points.min(axis=0)) / size).astype(np.int64) + 1
    dims = cell.max(axis=0) + 2
    key = (cell[:, 0] * dims[1] + cell[:, 1]) * dims[2] + cell[:, 2]
    cells, of_point = np.unique(key, return_inverse=True)
    first, second = [], []
    for dx, dy, dz in [(dx, dy, dz) for dx in (-1, 0, 1) for dy in (-1, 0, 1) for dz in (-1, 0, 1)
                       if (dx, dy, dz) > (0, 0, 0)]:
        neighbor = cells + (dx * dims[1] + dy) * dims[2] + dz
        at = np.minimum(np.searchsorted(cells, neighbor), len(cells) - 1)
        found = cells[at] == neighbor
        first.append(np.flatnonzero(found))
        second.append(at[found])
    first, second = np.concatenate(first), np.concatenate(second)
    label = np.arange(len(cells))
    while True:  # the smallest cell of each group, by propagation and pointer jumping
        smaller = np.minimum(label[first], label[second])
        before = label.copy()
        np.minimum.at(label, first, smaller)
        np.minimum.at(label, second, smaller)
        label = label[label]
        if np.array_equal(label, before):
            break
    return np.unique(label, return_inverse=True)[1][of_point]


def _record_dtype(has_normals):
    fields = [("index", "<i8"), ("p", "<f8", (3,))]
    return np.dtype(fields + [("n", "<f8", (3,))] if has_normals else fields)


def _tile_path(folder, tile, kind):
    return os.path.join(folder, "tiles", f"tile_{tile:05d}.{kind}")


def _write_tile_files(cloud, tree, tiles, folder, margin, kind):
    """Streams the cloud once and writes per tile its points within ``margin``
    of its box (``kind`` "core" with margin 0, else "halo": those outside its core)."""
    dtype = _record_dtype(cloud.has_normals)
    temporary = {t: _tile_path(folder, t, kind) + ".tmp" for t in range(tiles)}
    for path in temporary.values():
        open(path, "wb").close()
    for start, points, normals in cloud.chunks(CHUNK):
        owner = _owner(tree, points) if kind == "halo" else None
        for tile, rows in _assign(tree, points, margin).items():
            if owner is not None:
                rows = rows[owner[rows] != tile]
            if not len(rows):
                continue
            records = np.empty(len(rows), dtype)
            records["index"] = start + rows
            records["p"] = points[rows]
            if normals is not None:
                records["n"] = normals[rows]
            with open(temporary[tile], "ab") as f:
                records.tofile(f)
    for tile, path in temporary.items():
        os.replace(path, _tile_path(folder, tile, kind))
    return [os.path.getsize(_tile_path(folder, t, kind)) // dtype.itemsize for t in range(tiles)]


def _load_tile(folder, tile, has_normals, with_halo=True):
    """A tile's points in input order: (index, points, normals or None, is_core)."""
    dtype = _record_dtype(has_normals)
    core = np.fromfile(_tile_path(folder, tile, "core"), dtype=dtype)
    halo = np.fromfile(_tile_path(folder, tile, "halo"), dtype=dtype) if with_halo else np.empty(0, dtype)
    records = np.concatenate([core, halo])
    is_core = np.concatenate([np.ones(len(core), bool), np.zeros(len(halo), bool)])
    order = np.argsort(records["index"], kind="stable")
    records, is_core = records[order], is_core[order]
    normals = np.ascontiguousarray(records["n"]) if has_normals else None
    return records["index"], np.ascontiguousarray(records["p"]), normals, is_core


# --- the tasks run on the workers ------------------------------------------------

def _peak_memory():
    """This process's peak resident memory in bytes and its id."""
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024, os.getpid()


def _tile_noise(folder, tile, has_normals):
    """The noise estimate of a tile's core points: their number and spacing."""
    from . import estimate_noise
    _, points, _, _ = _load_tile(folder, tile, has_normals, with_halo=False)
    return {"core": len(points), "spacing": estimate_noise(points).spacing}


def _tile_outliers(folder, tile, has_normals):
    """A tile's outlier flags (the input rule on the tile with its halo), and
    its kept core points' coordinates, sorted per axis, for the global center."""
    from . import _native
    index, points, _, is_core = _load_tile(folder, tile, has_normals)
    outlier = _native.input_outliers(points)
    tile_io.save_array(_tile_path(folder, tile, "outlier.npy"), outlier)
    kept = points[is_core & ~outlier]
    for axis in range(3):
        values = np.sort(kept[:, axis])
        tile_io.save_array(_tile_path(folder, tile, f"axis{axis}.npy"), values)
    return {"kept": len(kept), "outliers": index[is_core & outlier].tolist(), "core": int(is_core.sum())}


def _kept_points(folder, tile, has_normals, core_only):
    """A tile's points that are not outliers: (index, points, is_core)."""
    index, points, _, is_core = _load_tile(folder, tile, has_normals)
    kept = ~np.load(_tile_path(folder, tile, "outlier.npy"))
    if core_only:
        kept &= is_core
    return index[kept], points[kept], is_core[kept]


def _tile_half_radii(folder, tile, has_normals, center):
    """Saves the sorted half radii of a tile's kept core points about ``center``
    (the robust size's measure: the largest halved coordinate difference)."""
    _, points, _ = _kept_points(folder, tile, has_normals, True)
    values = np.sort(np.abs(points / 2 - np.asarray(center) / 2).max(axis=1))
    tile_io.save_array(_tile_path(folder, tile, "radius.npy"), values)
    return {"kept": len(values)}


def _normalized(points, center, exponent):
    """(p - c) / 2^e as the pipeline's working frame rounds it (halves, then an exact scaling)."""
    return np.ldexp(points / 2 - np.asarray(center) / 2, 1 - exponent)


def _mix_hash(h, x):
    """SplitMix64's finalizer of ``h`` with ``x`` mixed in (order_free.h's mix_hash)."""
    h = (h ^ x) + np.uint64(0x9E3779B97F4A7C15)
    h = (h ^ (h >> np.uint64(30))) * np.uint64(0xBF58476D1CE4E5B9)
    h = (h ^ (h >> np.uint64(27))) * np.uint64(0x94D049BB133111EB)
    return h ^ (h >> np.uint64(31))


def _coordinate_hash(q):
    """order_free.h's coordinate_hash of each row of ``q`` (+0 and -0 alike)."""
    h = np.zeros(len(q), dtype=np.uint64)
    with np.errstate(over="ignore"):
        for axis in range(3):
            h = _mix_hash(h, np.ascontiguousarray(q[:, axis] + 0.0).view(np.uint64))
    return h


def _smallest_keys(index, q, count):
    """The rows of the ``count`` smallest order-free keys (hash, x, y, z, then input index)."""
    order = np.lexsort((index, q[:, 2], q[:, 1], q[:, 0], _coordinate_hash(q)))
    return order[:count]


def _tile_noise_sample(folder, tile, has_normals, center, exponent, count):
    """A tile's kept core points with the ``count`` smallest order-free keys
    in the working frame: (input indices, normalized points)."""
    index, points, _ = _kept_points(folder, tile, has_normals, True)
    q = _normalized(points, center, exponent)
    rows = _smallest_keys(index, q, count)
    return index[rows], q[rows]


def _tile_noise_neighbors(folder, tile, has_normals, center, exponent, sample, neighbors):
    """The kept points of a tile (core and halo) among the ``neighbors`` nearest
    of each of its ``sample`` indices, ties included: (indices, normalized points)."""
    index, points, _ = _kept_points(folder, tile, has_normals, False)
    q = _normalized(points, center, exponent)
    rows = np.searchsorted(index, sample)
    chosen = []
    for row in rows:
        distance = ((q - q[row]) ** 2).sum(axis=1)
        k = min(neighbors, len(q) - 1)
        limit = np.partition(distance, k)[k]
        chosen.append(np.flatnonzero(distance <= limit * (1 + 1e-9)))
    chosen = np.unique(np.concatenate(chosen)) if chosen else np.empty(0, np.int64)
    return index[chosen], q[chosen]


class _TileShape:
    """A tile's points and its job, the shape built (``conformal_alpha_shapes._job``).

    A future holds one on its worker between the closing values and the
    curvature. Moved to another worker or spilled, it travels as its tile and
    options only, and is built again by the task that uses it.
    """

    def __init__(self, folder, tile, has_normals, job, build=True):
        self.arguments = (folder, tile, has_normals, job)
        self.index, self.points, self.normals, self.is_core = _load_tile(folder, tile, has_normals)
        self.native = self._build() if build else None

    def _build(self):
        from . import _job
        job = self.arguments[3]
        return _job(self.points, self.normals, radii=job["radii"], rings=job["rings"],
                    estimator=job["estimator"], denoise=job["denoise"], denoise_neighbors=job["denoise_neighbors"],
                    extraction=job["extraction"], threads=job["threads"], spacing=job["spacing"],
                    noise=job["noise"])

    def built(self):
        """The native job, built here if it came unbuilt."""
        if self.native is None:
            self.native = self._build()
        return self.native

    def __reduce__(self):
        return (_TileShape, self.arguments + (False,))


def _shape_size(shape):
    """What a held shape weighs, for Dask's memory accounting."""
    return SHAPE_BYTES_PER_POINT * len(shape.points)


def _register_shape_size():
    from dask.sizeof import sizeof
    sizeof.register(_TileShape)(_shape_size)


_register_shape_size()


def _tile_shape(folder, tile, has_normals, job):
    """A tile's shape, to be held on its worker."""
    return _TileShape(folder, tile, has_normals, job)


def _tile_closing(folder, tile, has_normals, job, shape=None):
    """Writes the sorted closing values of a tile's core points (of ``shape``,
    held on this worker, or of a shape built here); returns their number."""
    started = time.monotonic()
    held = shape is not None
    shape = shape if held else _TileShape(folder, tile, has_normals, job)
    closing = shape.built().closing_values()
    if not held:
        shape.native.release()
    values = np.sort(closing[shape.is_core & ~np.isnan(closing)])
    tile_io.save_array(os.path.join(folder, "tiles", f"closing_{tile:05d}.npy"), values)
    return {"count": len(values), "seconds": time.monotonic() - started, "memory": _peak_memory(),
            "points": len(shape.points), "core": int(shape.is_core.sum())}


def _scale_text(a):
    """The program's text of a scale value (std::to_string, zeros dropped)."""
    text = ("%f" % a).rstrip("0")
    return text[:-1] if text.endswith(".") else text


def _flip_layer(records, name, rows):
    """The values of layer ``name`` at ``rows`` as seen from the other side of the surface."""
    for axis in ("x", "y", "z"):
        records[f"n{axis}_{name}"][rows] *= -1
        d1, d2 = records[f"d1{axis}_{name}"][rows], records[f"d2{axis}_{name}"][rows]
        records[f"d1{axis}_{name}"][rows], records[f"d2{axis}_{name}"][rows] = d2, d1
    records[f"H_{name}"][rows] *= -1
    k1, k2 = records[f"k1_{name}"][rows], records[f"k2_{name}"][rows]
    records[f"k1_{name}"][rows], records[f"k2_{name}"][rows] = -k2, -k1


def _part_path(folder, tile):
    return os.path.join(folder, "parts", f"part_{tile:05d}.ply")


def _tile_curvatures(folder, tile, has_normals, job, center, tree, shape=None):
    """A tile's curvature (of ``shape``, held on this worker, or of a shape
    built here): its part (core points), its seam file (halo points' normals,
    per scale) and what the driver needs (layer names, cone sums)."""
    from . import Result, _option_items
    started = time.monotonic()
    shape = shape if shape is not None else _TileShape(folder, tile, has_normals, job)
    index, points, is_core = shape.index, shape.points, shape.is_core
    native = shape.built()
    result = Result(points, native.result(_option_items(job["tile_scales"], "scales"), None))
    native.release()
    per_scale = len(result.layers) // len(job["scales"])
    names, descriptions = [], {}
    for k, tile_name in enumerate(result.layers):
        scale = job["scales"][k // per_scale]
        layer = result[tile_name]
        name, description = tile_name, layer.description
        if scale == "auto":
            text = _scale_text(layer.a)
            description = description.replace(f"({text})", "(auto)", 1)
            if len(job["scales"]) > 1:
                name = "auto_" + tile_name.split("_", 1)[1]
        names.append(name)
        descriptions[name] = description
    core = np.flatnonzero(is_core)
    records = np.zeros(len(core), tile_io.part_dtype(names))
    for axis, column in zip("xyz", points[core].T):
        records[axis] = column
    records["outlier"] = result.outlier[core]
    records["input_index"] = index[core]
    for name, tile_name in zip(names, result.layers):
        layer = result[tile_name]
        for i, axis in enumerate("xyz"):
            records[f"n{axis}_{name}"] = layer.normal[core, i]
            records[f"d1{axis}_{name}"] = layer.d1[core, i]
            records[f"d2{axis}_{name}"] = layer.d2[core, i]
        for key in ("H", "K", "k1", "k2", "radius", "distance", "source"):
            records[f"{key}_{name}"] = getattr(layer, key)[core]
    first_layers = [result[result.layers[s * per_scale]] for s in range(len(job["scales"]))]
    halo = np.flatnonzero(~is_core)
    seam = os.path.join(folder, "tiles", f"seam_{tile:05d}.npy")
    seam_normals = np.stack([layer.normal[halo].astype(np.float32) for layer in first_layers])
    component = _components(points, COMPONENT_CELL_SPACINGS * job["spacing"])
    tile_io.save_array(_tile_path(folder, tile, "component.npy"), component[core])
    seam_records = np.empty(len(halo), [("index", "<i8"), ("owner", "<i4"), ("component", "<i4"),
                                        ("normal", "<f4", (len(first_layers), 3))])
    seam_records["index"] = index[halo]
    seam_records["owner"] = _owner(tree, points[halo])
    seam_records["component"] = component[halo]
    seam_records["normal"] = np.moveaxis(seam_normals, 0, 1)
    tile_io.save_array(seam, seam_records)
    # the cone each scale's surface spans from the cloud's center, on the core's own vertices
    # per scale and object, the cone its surface spans from the cloud's center, on the core's own vertices
    cones = []
    for layer in first_layers:
        own = core[layer.source[core] == 0]
        terms = np.einsum("ij,ij->i", layer.normal[own], points[own] - np.asarray(center))
        cones.append(np.bincount(component[own], weights=terms, minlength=int(component.max()) + 1).tolist())
    part = _part_path(folder, tile)
    tile_io.write_part(part, records, names, descriptions)
    sizes = np.bincount(component[core], minlength=int(component.max()) + 1).tolist()
    return {"names": names, "descriptions": descriptions, "cones": cones, "sizes": sizes,
            "size": os.path.getsize(part),
            "sha256": tile_io.file_digest(part), "seconds": time.monotonic() - started,
            "memory": _peak_memory(), "points": len(points), "core": len(core),
            "a": [layer.a for layer in first_layers]}


def _tile_votes(folder, tile, names, first_names, states):
    """Votes of a tile's halo points against their owners' parts, both taken
    unflipped (``states``: per tile and scale, the objects its part carries
    turned): ``[(scale, this tile's object, owner, its object, agree, disagree)]``."""
    seam = np.load(os.path.join(folder, "tiles", f"seam_{tile:05d}.npy"))
    votes = []
    for owner in np.unique(seam["owner"]):
        owner = int(owner)
        mine = seam[seam["owner"] == owner]
        part = tile_io.read_part(_part_path(folder, owner), names)
        rows = np.searchsorted(part["input_index"].astype(np.int64), mine["index"])
        theirs_component = np.load(_tile_path(folder, owner, "component.npy"))[rows]
        for s, name in enumerate(first_names):
            theirs = np.column_stack([part[f"n{axis}_{name}"][rows] for axis in "xyz"]).astype(np.float64)
            sign = np.where(np.isin(theirs_component, states[owner][s]), -1.0, 1.0)
            dot = sign * np.einsum("ij,ij->i", theirs, mine["normal"][:, s, :].astype(np.float64))
            valid = np.isfinite(dot) & (dot != 0)
            pairs = np.column_stack([mine["component"][valid], theirs_component[valid]])
            for (a, b), count in zip(*np.unique(pairs, axis=0, return_counts=True)):
                both = valid.copy()
                both[valid] = (pairs[:, 0] == a) & (pairs[:, 1] == b)
                votes.append((s, int(a), owner, int(b), int((dot[both] > 0).sum()), int((dot[both] < 0).sum())))
    return votes


def _tile_flip(folder, tile, names, scale_layers, turns):
    """Rewrites a part with the layers of each scale ``s`` turned over at the
    points of the objects ``turns[s]`` (which toggle what the part carries)."""
    path = _part_path(folder, tile)
    header = tile_io.part_header(path)
    records = np.array(tile_io.read_part(path, names))
    component = np.load(_tile_path(folder, tile, "component.npy"))
    for s, objects in turns.items():
        rows = np.flatnonzero(np.isin(component, objects))
        for name in scale_layers[s]:
            _flip_layer(records, name, rows)

    def write(temporary):
        with open(temporary, "wb") as f:
            f.write(header)
            records.tofile(f)
    tile_io.atomic_write(path, write)
    return {"size": os.path.getsize(path), "sha256": tile_io.file_digest(path)}


# --- the driver ----------------------------------------------------------------

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


def _kth_smallest(paths, k):
    """The ``k``-th smallest (from 0) of the values of sorted ``.npy`` files
    pooled, exactly: a bisection over the doubles' bit patterns, counting
    with a binary search in each file (memory-mapped)."""
    arrays = [a for a in (np.load(path, mmap_mode="r") for path in paths) if len(a)]
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


def _arguments_hash(input_path, options):
    """What makes two runs the same: the input file (path, size, time) and the options."""
    stat = os.stat(input_path)
    text = json.dumps([os.path.abspath(input_path), stat.st_size, stat.st_mtime_ns, options], sort_keys=True)
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
    workers = workers or max(1, os.cpu_count() or 1)
    memory = os.sysconf("SC_PAGE_SIZE") * os.sysconf("SC_PHYS_PAGES")
    cluster = LocalCluster(n_workers=workers, threads_per_worker=1, processes=True, host="127.0.0.1",
                           dashboard_address=None, memory_limit=memory // workers)
    return Client(cluster), cluster


def process_tiles(input, output, *, tile_points=1_000_000, workers=None, scheduler=None, security=None,
                  client=None, merge=False, scales=("auto",), radii=("auto", "2s", "4s", "8s", "16s"),
                  rings=(), estimator="quadric", denoise="auto", denoise_neighbors=None, extraction="front",
                  halo=None, threads=1, quiet=False):
    """The program's job on a cloud split into tiles, on a Dask cluster.

    Parameters:
        input: a binary PLY (float or double x y z, optional nx ny nz), a
            ``.npy`` of shape (N, 3) or (N, 6) (memory-mapped) or a ``.xyz``.
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
        scales, radii, rings, estimator, denoise, denoise_neighbors,
        extraction: as ``multiscale_curvatures`` (scales: "auto" and values).
        halo: the halo's width in spacings (default ``halo_spacings()``).
        threads: threads per tile (TBB); the cluster runs one tile per worker thread.
        quiet: no progress and no summary on the terminal.

    Returns:
        The summary (a dict): tiles, points, spacing, noise, denoised, a per
        scale, halo, the seams' agreement, the worst tile, workers' peak memory.

    Raises:
        tile_io.InputError: bad input (file and line), before any file is written.
        ValueError, TypeError: bad options, as ``multiscale_curvatures``.
    """
    options = {"scales": [str(x) for x in ((scales,) if isinstance(scales, (str, float, int)) else scales)],
               "radii": [str(x) for x in ((radii,) if isinstance(radii, (str, float, int)) else radii)],
               "rings": [int(x) for x in ((rings,) if isinstance(rings, int) else rings)],
               "estimator": estimator, "denoise": {True: "on", False: "off"}.get(denoise, denoise),
               "denoise_neighbors": denoise_neighbors, "extraction": extraction,
               "tile_points": int(tile_points), "halo": halo}
    _check_options(options)
    input = os.fspath(input)
    cloud = tile_io.open_cloud(input)
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
        tile_io.merge_parts(os.path.join(output, "curvatures.ply"),
                            [_part_path(output, t) for t in range(manifest["tiles"])], names,
                            manifest["descriptions"], cloud.count)
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
        sample = np.concatenate([p[(-start) % stride::stride] for start, p, _ in cloud.chunks(CHUNK)])
        tiles = max(1, math.ceil(cloud.count / options["tile_points"]))
        tree = _split(sample, tiles, 0)
        core = _write_tile_files(cloud, tree, tiles, output, 0.0, "core")
        total = np.zeros(3)
        for _, p, _ in cloud.chunks(CHUNK):
            total += p.sum(axis=0)
        manifest.update(tree=tree, tiles=tiles, core=core, center=(total / cloud.count).tolist())
        save()
    tiles, tree = manifest["tiles"], manifest["tree"]
    if "first_spacing" not in manifest:
        estimates = {}
        _run_tasks(client, _tile_noise, [(t, (output, t, has_normals)) for t in range(tiles)], "first spacing",
                   cloud.count, quiet, lambda t, value: estimates.__setitem__(t, value))
        counts = np.array([estimates[t]["core"] for t in range(tiles)], dtype=np.float64)
        first_spacing = float(np.average([estimates[t]["spacing"] for t in range(tiles)], weights=counts))
        _write_tile_files(cloud, tree, tiles, output, NEAR_HALO_SPACINGS * first_spacing, "halo")
        manifest.update(first_spacing=first_spacing)
        save()
    if "spacing" not in manifest:
        manifest.update(_global_noise(client, cloud, output, tiles, quiet))
        calls = manifest["noise"] > 0.02 and manifest["noise_24"] <= 1.3 * manifest["noise"]
        manifest["denoise"] = options["denoise"] if options["denoise"] != "auto" else ("on" if calls else "off")
        save()
    if "halo_spacings" not in manifest:
        halo = options["halo"] or halo_spacings(options["radii"], options["rings"], manifest["spacing"])
        _write_tile_files(cloud, tree, tiles, output, halo * manifest["spacing"], "halo")
        manifest.update(halo_spacings=halo)
        save()


def _global_noise(client, cloud, output, tiles, quiet):
    """The noise estimate of one run, from the tiles: the outliers left out,
    the working frame (the kept points' per-axis median and robust size, by
    exact selection over the tiles), the sample of the points with the
    smallest order-free keys in that frame, and ``estimate_noise()`` on that
    sample with the neighbors of its fits, which it gives as on the whole cloud."""
    from . import estimate_noise
    has_normals = cloud.has_normals
    kept, outliers = {}, []

    def outliers_done(t, value):
        kept[t] = value["kept"]
        outliers.extend(value["outliers"])
    _run_tasks(client, _tile_outliers, [(t, (output, t, has_normals)) for t in range(tiles)], "outliers",
               cloud.count, quiet, outliers_done)
    n = sum(kept.values())
    center = [_kth_smallest([_tile_path(output, t, f"axis{axis}.npy") for t in range(tiles)], n // 2)
              for axis in range(3)]
    _run_tasks(client, _tile_half_radii, [(t, (output, t, has_normals, center)) for t in range(tiles)],
               "working frame", cloud.count, True, lambda t, value: None)
    radii = [_tile_path(output, t, "radius.npy") for t in range(tiles)]
    h = _kth_smallest(radii, n // 2)
    if not h > 0:
        h = max(float(np.load(path, mmap_mode="r")[-1]) for path in radii if kept[radii.index(path)])
    exponent = int(np.frexp(h)[1]) + 1 if h > 0 else 0  # ilogb(h) + 2
    futures = [client.submit(_tile_noise_sample, output, t, has_normals, center, exponent, NOISE_SAMPLE,
                             retries=3, pure=False) for t in range(tiles)]
    samples = client.gather(futures)
    index = np.concatenate([s[0] for s in samples])
    q = np.concatenate([s[1] for s in samples])
    owner = np.concatenate([np.full(len(s[0]), t) for t, s in enumerate(samples)])
    chosen = _smallest_keys(index, q, NOISE_SAMPLE)
    futures = [client.submit(_tile_noise_neighbors, output, t, has_normals, center, exponent,
                             np.sort(index[chosen][owner[chosen] == t]), NOISE_NEIGHBORS, retries=3, pure=False)
               for t in range(tiles) if np.any(owner[chosen] == t)]
    found = client.gather(futures)
    index = np.concatenate([f[0] for f in found])
    q = np.concatenate([f[1] for f in found])
    _, rows = np.unique(index, return_index=True)
    estimate = estimate_noise(q[rows])
    return {"spacing": float(np.ldexp(estimate.spacing, exponent)), "noise": float(estimate),
            "noise_24": estimate.noise_24, "outliers": len(outliers), "working_frame": [center, exponent]}


def _automatic_scale(client, cloud, output, manifest, save, job, shapes, quiet):
    """The automatic scale of the whole cloud: the 0.99 quantile of the core
    points' closing values of all tiles pooled (exact: one run's rule)."""
    if "a" in manifest:
        return manifest["a"]
    tiles = manifest["tiles"]
    counts, stats = {}, {}

    def done(t, value):
        counts[t] = value["count"]
        stats[t] = value
    _run_tasks(client, _tile_closing,
               [(t, (output, t, cloud.has_normals, job, shapes.get(t))) for t in range(tiles)],
               "closing values", cloud.count, quiet, done)
    n = sum(counts.values())
    k = min(n - 1, int(COVERAGE * n))
    a = _kth_smallest([os.path.join(output, "tiles", f"closing_{t:05d}.npy") for t in range(tiles)], k)
    manifest.update(a=a, closing_stats={str(t): {"seconds": v["seconds"], "memory": v["memory"]}
                                        for t, v in stats.items()})
    save()
    return a


def _part_is_finished(output, tile, entry):
    """Whether a part on disk is the one the manifest records (size and SHA-256)."""
    path = _part_path(output, tile)
    return (entry is not None and os.path.exists(path) and os.path.getsize(path) == entry["size"]
            and tile_io.file_digest(path) == entry["sha256"])


def _orient(votes, parts, scales, has_normals):
    """Per tile and scale, the objects (``_components``) its part is to carry
    turned over: an object is turned when its seam to the object it was
    reached from votes to disagree (from the largest object, by the strongest
    seams); each group of objects so joined faces away from the cloud's
    center, as one run's sheets do (outward for a closed one); with input
    normals, none."""
    turned = [[[] for _ in range(scales)] for _ in parts]
    if has_normals:
        return turned
    units = [(t, c) for t, part in enumerate(parts) for c in range(len(part["sizes"]))]
    for s in range(scales):
        edges = {}
        for t, tile_votes in votes.items():
            for scale, mine, owner, theirs, agree, disagree in tile_votes:
                if scale == s:
                    pair = tuple(sorted([(t, mine), (owner, theirs)]))
                    counts = edges.setdefault(pair, [0, 0])
                    counts[0] += agree
                    counts[1] += disagree
        neighbors = {unit: [] for unit in units}
        for (a, b), (agree, disagree) in edges.items():
            if agree + disagree >= MINIMUM_SEAM_POINTS:
                neighbors[a].append((abs(agree - disagree), b, disagree > agree))
                neighbors[b].append((abs(agree - disagree), a, disagree > agree))
        relative = {}
        for root in sorted(units, key=lambda unit: -parts[unit[0]]["sizes"][unit[1]]):
            if root in relative:
                continue
            relative[root] = False
            group, frontier = [root], [(0, root)]
            while frontier:  # the strongest seam out of the group first
                frontier.sort()
                _, unit = frontier.pop()
                for strength, other, opposite in neighbors[unit]:
                    if other not in relative:
                        relative[other] = relative[unit] ^ opposite
                        group.append(other)
                        frontier.append((strength, other))
            cone = sum(-parts[t]["cones"][s][c] if relative[(t, c)] else parts[t]["cones"][s][c] for t, c in group)
            for t, c in group:
                if relative[(t, c)] ^ (cone < 0):
                    turned[t][s].append(c)
    return turned


def _shapes_fit(client, output, manifest, has_normals):
    """Whether all tiles' shapes fit in the workers' memory at once (a share
    of their limits; a worker without a limit makes it unknown: no)."""
    limits = [worker.get("memory_limit") or 0 for worker in client.scheduler_info()["workers"].values()]
    if not limits or min(limits) <= 0:
        return False
    record = _record_dtype(has_normals).itemsize
    points = sum(manifest["core"]) + sum(os.path.getsize(_tile_path(output, t, "halo")) // record
                                         for t in range(manifest["tiles"]))
    return points * SHAPE_BYTES_PER_POINT <= HELD_SHAPES_SHARE * sum(limits)


def _run(client, cloud, output, options, manifest, save, threads, quiet):
    _partition(cloud, output, options, manifest, save, client, quiet)
    tiles = manifest["tiles"]
    job = dict(options, spacing=manifest["spacing"], noise=manifest["noise"], denoise=manifest["denoise"],
               threads=threads)
    parts = manifest["parts"]
    todo = [t for t in range(tiles) if not _part_is_finished(output, t, parts.get(str(t)))]
    reused = tiles - len(todo)
    closing = "auto" in options["scales"] and "a" not in manifest
    keep = closing and todo and _shapes_fit(client, output, manifest, cloud.has_normals)
    # futures of the shapes on their workers, from the closing values to the curvature
    shapes = {t: client.submit(_tile_shape, output, t, cloud.has_normals, job, retries=3, pure=False,
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
    _run_tasks(client, _tile_curvatures,
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
    _run_tasks(client, _tile_votes, [(t, (output, t, names, first_names, states)) for t in range(tiles)],
               "seams", 0, True, votes.__setitem__)
    flips = _orient(votes, [parts[str(t)] for t in range(tiles)], len(first_names), cloud.has_normals)
    changes = []
    for t in range(tiles):
        turns = {s: sorted(set(flips[t][s]) ^ set(states[t][s])) for s in range(len(first_names))}
        turns = {s: objects for s, objects in turns.items() if objects}
        if turns:
            changes.append((t, turns))

    def flipped(t, value):
        parts[str(t)].update(value, flips=flips[t])
        save()
    _run_tasks(client, _tile_flip, [(t, (output, t, names, scale_layers, turns)) for t, turns in changes],
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
                  if x is not None and n >= MINIMUM_SEAM_POINTS]
    return {"tiles": manifest["tiles"], "points": cloud.count, "spacing": manifest["spacing"],
            "noise": manifest["noise"], "denoised": manifest["denoise"] == "on",
            "a": parts["0"]["a"], "halo_spacings": manifest["halo_spacings"],
            "layers": parts["0"]["names"], "seams": seam_list,
            "worst_seam_agreement": min(agreements) if agreements else None,
            "worst_tile": {"tile": int(worst), "seconds": parts[worst]["seconds"],
                           "points": parts[worst]["points"], "core": parts[worst]["core"]},
            "tile_points_with_halo": sum(parts[t]["points"] for t in parts),
            "reused_parts": reused,
            "flipped": [[t, s, objects] for t, row in enumerate(flips) for s, objects in enumerate(row) if objects],
            "worker_peak_memory": {str(pid): size for pid, size in memory.items()},
            "shapes": manifest["shapes"]}


_SHAPES_TEXT = {
    "kept": "each tile's shape kept on its worker from the closing values to the curvature",
    "rebuilt": "each tile's shape built twice (closing values, curvature): the workers' memory cannot hold all",
    "built once": "each tile's shape built once"}


def format_summary(summary):
    """The summary as the program prints its own: a few lines of text."""
    seams = [s for s in summary["seams"] if max(s["points"]) >= MINIMUM_SEAM_POINTS]
    lines = [f"{summary['points']} points in {summary['tiles']} tiles "
             f"({summary['tile_points_with_halo']} with halos of {summary['halo_spacings']:.1f} spacings), "
             f"{summary['reused_parts']} parts reused",
             f"noise: {summary['noise']:.3g} x spacing (spacing {summary['spacing']:.4g}); "
             f"{'smoothed' if summary['denoised'] else 'no smoothing'}",
             "scales: " + ", ".join(f"a = {a:.4g}" for a in summary["a"]),
             _SHAPES_TEXT[summary["shapes"]],
             f"seams: {len(seams)}, worst agreement "
             + (f"{100 * summary['worst_seam_agreement']:.2f}%" if summary["worst_seam_agreement"] is not None
                else "none"),
             f"worst tile: {summary['worst_tile']['tile']}, {summary['worst_tile']['points']} points, "
             f"{summary['worst_tile']['seconds']:.1f} s",
             "workers' peak memory: " + ", ".join(f"{size / 2**30:.2f} GiB"
                                                  for size in summary["worker_peak_memory"].values()),
             f"{summary.get('seconds', 0):.1f} s"]
    return "\n".join(lines)


# the Python keywords in the module's messages, and the flags that set them
_FLAGS = {"scales": "--alpha", "radii": "--radius", "rings": "--rings", "estimator": "--estimator",
          "denoise_neighbors": "--denoise-neighbors", "denoise": "--denoise", "extraction": "--extraction",
          "tile_points": "--tile-points", "radii, rings": "--radius, --rings"}


def _flag_message(message):
    """A message of the module with the program's flag for the keyword it names."""
    for keyword in sorted(_FLAGS, key=len, reverse=True):
        if message.startswith(keyword + ":"):
            return _FLAGS[keyword] + message[len(keyword):]
    return message


def _arguments(argv):
    parser = argparse.ArgumentParser(
        prog="python3 -m conformal_alpha_shapes.tiles",
        description="The program conformal_curvature's job on a cloud split into tiles, on Dask: "
                    "parts in DIR/parts (binary PLY, the fields of curvatures.ply plus input_index), "
                    "DIR/manifest.json, and with --merge DIR/curvatures.ply in input order.")
    parser.add_argument("input", help="binary .ply (x y z [nx ny nz]), .npy (N x 3 or N x 6) or .xyz")
    parser.add_argument("--output", required=True, metavar="DIR",
                        help="the run's folder, readable and writable by every worker")
    parser.add_argument("--tile-points", type=int, default=1_000_000, metavar="N",
                        help="core points per tile (default 1000000)")
    engine = parser.add_mutually_exclusive_group()
    engine.add_argument("--workers", type=int, metavar="W",
                        help="worker processes of the embedded cluster on 127.0.0.1 (default: one per core)")
    engine.add_argument("--scheduler", metavar="ADDRESS", help="an existing Dask scheduler (tcp:// or tls://)")
    parser.add_argument("--tls-ca-file", help="TLS: the certificate authority's file (with --scheduler)")
    parser.add_argument("--tls-cert", help="TLS: this client's certificate")
    parser.add_argument("--tls-key", help="TLS: this client's private key")
    parser.add_argument("--merge", action="store_true", help="also write DIR/curvatures.ply in input order")
    parser.add_argument("--alpha", default="auto", metavar="LIST", help="comma list of scales: auto and/or values")
    parser.add_argument("--radius", default=None, metavar="LIST",
                        help="comma list of radii: values, multiples of the spacing (4s), auto; "
                             "default auto,2s,4s,8s,16s unless --rings is given")
    parser.add_argument("--rings", default="", metavar="LIST", help="comma list of ring sizes from 1 to 100")
    parser.add_argument("--estimator", default="quadric", metavar="NAME")
    parser.add_argument("--denoise", default="auto", metavar="MODE", help="auto, on or off")
    parser.add_argument("--denoise-neighbors", default=None, metavar="K")
    parser.add_argument("--extraction", default="front", metavar="NAME", help="front or solid")
    parser.add_argument("--halo", type=float, default=None, metavar="SPACINGS",
                        help="the halo's width in spacings (default: from the largest radius, see the manual)")
    parser.add_argument("--threads", type=int, default=1, help="threads per tile (default 1)")
    parser.add_argument("--quiet", action="store_true", help="no progress and no summary")
    return parser.parse_args(argv)


def _split_list(text):
    return [item for item in text.split(",") if item] if text else []


def main(argv=None):
    """The command line; returns the exit status (1 with one line on stderr on failure)."""
    args = _arguments(argv)
    rings = _split_list(args.rings)
    radii = _split_list(args.radius) if args.radius is not None else ([] if rings else
                                                                      ["auto", "2s", "4s", "8s", "16s"])
    security = None
    if args.tls_ca_file or args.tls_cert or args.tls_key:
        from distributed.security import Security
        security = Security(tls_ca_file=args.tls_ca_file, tls_client_cert=args.tls_cert,
                            tls_client_key=args.tls_key, require_encryption=True)
    try:
        ring_sizes = []
        for ring in rings:
            try:
                ring_sizes.append(int(ring))
            except ValueError:
                raise ValueError(f"rings: not a ring size: '{ring}' (expected an integer from 1 to 100)") from None
        neighbors = None
        if args.denoise_neighbors is not None:
            try:
                neighbors = int(args.denoise_neighbors)
            except ValueError:
                raise ValueError(f"denoise_neighbors: not an integer: '{args.denoise_neighbors}'") from None
        process_tiles(args.input, args.output, tile_points=args.tile_points, workers=args.workers,
                      scheduler=args.scheduler, security=security, merge=args.merge,
                      scales=_split_list(args.alpha), radii=radii, rings=ring_sizes, estimator=args.estimator,
                      denoise=args.denoise, denoise_neighbors=neighbors, extraction=args.extraction,
                      halo=args.halo, threads=args.threads, quiet=args.quiet)
    except KeyboardInterrupt:
        print("conformal_alpha_shapes.tiles: interrupted; run again with the same arguments to finish",
              file=sys.stderr)
        return 130
    except (ValueError, TypeError, OSError) as e:
        print(f"conformal_alpha_shapes.tiles: {_flag_message(str(e))}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
