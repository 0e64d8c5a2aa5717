"""The partition: the cloud cut into spatial tiles, each tile's core and halo
points written to the run's folder and read back, a tile's separate objects,
and where the run's files lie."""

import os

import numpy as np

# Points read from the cloud at a time (their arrays take about 100 bytes each).
CHUNK = 1 << 18
# The cells, in spacings, whose touching joins the points of one object.
COMPONENT_CELL_SPACINGS = 3.0
# The halo's outer band, in spacings, whose surface borders (the halo's
# edge, not the scan's) may join a tile's open sheets across gaps that one
# run would not join: twice the gap that the join bridges, 8 local spacings
# (C++: join_open_sheets_across_gaps in internal/orient_surface_parts.h).
JOINED_GAP_SPACINGS = 16.0


def split(sample, tiles, first, band):
    """A tree of cuts over ``sample``: a leaf is a tile number, a node
    ``[axis, cut, left, right]`` sends points below ``cut`` left. Each cut is
    at the share of the tiles on each side, on the axis whose cut has the
    fewest points within ``band`` of it (the halo it adds; ties: the longest
    axis): a cut along a sheet, such as the ground under a horizontal cut,
    would put the whole sheet in the halos."""
    if tiles == 1:
        return first
    left = tiles // 2
    extent = sample.max(axis=0) - sample.min(axis=0)
    best = None
    for axis in range(3):
        cut = float(np.quantile(sample[:, axis], left / tiles))
        crossing = int(np.count_nonzero(np.abs(sample[:, axis] - cut) < band))
        if best is None or (crossing, -extent[axis]) < best[0]:
            best = ((crossing, -extent[axis]), axis, cut)
    _, axis, cut = best
    below = sample[:, axis] < cut
    return [axis, cut, split(sample[below], left, first, band),
            split(sample[~below], tiles - left, first + left, band)]


def assign(tree, points, margin, index=None, out=None):
    """Per tile, the rows of ``points`` within ``margin`` of its box (0: its core)."""
    if out is None:
        out, index = {}, np.arange(len(points))
    if not isinstance(tree, list):
        out[tree] = index
        return out
    axis, cut, left, right = tree
    values = points[index, axis]
    assign(left, points, margin, index[values < cut + margin], out)
    assign(right, points, margin, index[values >= cut - margin], out)
    return out


def owners(tree, points):
    """The tile whose core holds each point."""
    owner = np.empty(len(points), dtype=np.int32)
    for tile, rows in assign(tree, points, 0.0).items():
        owner[rows] = tile
    return owner


def components(points, size):
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
    return _connected(len(cells), np.concatenate(first), np.concatenate(second))[of_point]


def _connected(nodes, first, second):
    """Labels (0, 1, ...) of the connected parts of the graph of ``nodes``
    nodes whose edges join ``first[k]`` and ``second[k]``."""
    label = np.arange(nodes)
    while True:  # the smallest node of each part, by propagation and pointer jumping
        smaller = np.minimum(label[first], label[second])
        before = label.copy()
        np.minimum.at(label, first, smaller)
        np.minimum.at(label, second, smaller)
        label = label[label]
        if np.array_equal(label, before):
            break
    return np.unique(label, return_inverse=True)[1]


def surface_objects(component, surface, inner):
    """Per point, its object at one scale, numbered from 0: its ``component``
    joined with the others that share an orientation group of ``surface``
    (a scale's surface of the tile's run: the faces that one run's vote
    turns together, open sheets joined across gaps included), for the groups
    whose points are all ``inner`` (far enough from the halo's outer edge
    that no border there took part in their joins)."""
    group = np.full(len(component), -1, np.int64)
    group[surface["point_index"][surface["faces"]].ravel()] = np.repeat(surface["orientation_group"], 3)
    groups = int(group.max()) + 1
    outer = np.zeros(groups + 1, bool)
    outer[group[~inner]] = True  # index -1: points off the surface
    joined = ~outer[group] & (group >= 0)
    objects = int(component.max()) + 1
    label = _connected(objects + groups, component[joined], objects + group[joined])
    return np.unique(label[:objects], return_inverse=True)[1][component]


def record_dtype(has_normals):
    fields = [("index", "<i8"), ("p", "<f8", (3,))]
    return np.dtype(fields + [("n", "<f8", (3,))] if has_normals else fields)


def tile_path(folder, tile, kind):
    return os.path.join(folder, "tiles", f"tile_{tile:05d}.{kind}")


def part_path(folder, tile):
    return os.path.join(folder, "parts", f"part_{tile:05d}.ply")


def write_tile_files(cloud, tree, tiles, folder, margin, kind):
    """Streams the cloud once and writes per tile its points within ``margin``
    of its box (``kind`` "core" with margin 0, else "halo": those outside its core)."""
    dtype = record_dtype(cloud.has_normals)
    temporary = {t: tile_path(folder, t, kind) + ".tmp" for t in range(tiles)}
    for path in temporary.values():
        open(path, "wb").close()
    for start, points, normals in cloud.chunks(CHUNK):
        owner = owners(tree, points) if kind == "halo" else None
        for tile, rows in assign(tree, points, margin).items():
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
        os.replace(path, tile_path(folder, tile, kind))
    return [os.path.getsize(tile_path(folder, t, kind)) // dtype.itemsize for t in range(tiles)]


def load_tile(folder, tile, has_normals, with_halo=True):
    """A tile's points in input order: (index, points, normals or None, is_core)."""
    dtype = record_dtype(has_normals)
    core = np.fromfile(tile_path(folder, tile, "core"), dtype=dtype)
    halo = np.fromfile(tile_path(folder, tile, "halo"), dtype=dtype) if with_halo else np.empty(0, dtype)
    records = np.concatenate([core, halo])
    is_core = np.concatenate([np.ones(len(core), bool), np.zeros(len(halo), bool)])
    order = np.argsort(records["index"], kind="stable")
    records, is_core = records[order], is_core[order]
    normals = np.ascontiguousarray(records["n"]) if has_normals else None
    return records["index"], np.ascontiguousarray(records["p"]), normals, is_core
