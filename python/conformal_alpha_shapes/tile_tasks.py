"""The tasks the workers run on a tile before its orientation: the noise
estimate, the outliers, its share of the working frame and of the noise
sample, and its shape's closing values and curvatures."""

import os
import resource
import time

import numpy as np

from . import curvature_file, tile_io, tile_partition

# What a tile's shape held between phases weighs per point with halo (the
# manual, "Tiled Processing on Dask", measures the weight).
SHAPE_BYTES_PER_POINT = 2300


def _peak_memory():
    """This process's peak resident memory in bytes and its id."""
    return resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024, os.getpid()


def tile_noise(folder, tile, has_normals):
    """The noise estimate of a tile's core points: their number and spacing."""
    from . import _unchecked_noise_estimate
    _, points, _, _ = tile_partition.load_tile(folder, tile, has_normals, with_halo=False)
    return {"core": len(points), "spacing": _unchecked_noise_estimate(points).spacing}


def tile_outliers(folder, tile, has_normals):
    """A tile's outlier flags (the input rule on the tile with its halo) and
    copies of earlier points, and its kept core points' coordinates (each
    point once), sorted per axis, for the global center."""
    from . import _native
    index, points, _, is_core = tile_partition.load_tile(folder, tile, has_normals)
    outlier, copy = _native.input_outliers(points)
    tile_io.save_array(tile_partition.tile_path(folder, tile, "outlier.npy"), outlier)
    tile_io.save_array(tile_partition.tile_path(folder, tile, "copy.npy"), copy)
    kept = points[is_core & ~outlier & ~copy]
    for axis in range(3):
        values = np.sort(kept[:, axis])
        tile_io.save_array(tile_partition.tile_path(folder, tile, f"axis{axis}.npy"), values)
    return {"kept": len(kept), "outliers": index[is_core & outlier].tolist(), "core": int(is_core.sum())}


def _kept_points(folder, tile, has_normals, core_only):
    """A tile's points that are not outliers, each point once: (index, points, is_core)."""
    index, points, _, is_core = tile_partition.load_tile(folder, tile, has_normals)
    kept = ~np.load(tile_partition.tile_path(folder, tile, "outlier.npy"))
    kept &= ~np.load(tile_partition.tile_path(folder, tile, "copy.npy"))
    if core_only:
        kept &= is_core
    return index[kept], points[kept], is_core[kept]


def tile_half_radii(folder, tile, has_normals, center):
    """Saves the sorted half radii of a tile's kept core points about ``center``
    (the robust size's measure: the largest halved coordinate difference)."""
    _, points, _ = _kept_points(folder, tile, has_normals, True)
    values = np.sort(np.abs(points / 2 - np.asarray(center) / 2).max(axis=1))
    tile_io.save_array(tile_partition.tile_path(folder, tile, "radius.npy"), values)
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


def smallest_keys(index, q, count):
    """The rows of the ``count`` smallest order-free keys (hash, x, y, z, then input index)."""
    order = np.lexsort((index, q[:, 2], q[:, 1], q[:, 0], _coordinate_hash(q)))
    return order[:count]


def tile_noise_sample(folder, tile, has_normals, center, exponent, count):
    """A tile's kept core points with the ``count`` smallest order-free keys
    in the working frame: (input indices, normalized points)."""
    index, points, _ = _kept_points(folder, tile, has_normals, True)
    q = _normalized(points, center, exponent)
    rows = smallest_keys(index, q, count)
    return index[rows], q[rows]


def tile_noise_neighbors(folder, tile, has_normals, center, exponent, sample, neighbors):
    """The kept points of a tile (core and halo) among the ``neighbors`` nearest
    of each of its ``sample`` indices, ties included: (indices, normalized points)."""
    from . import _native
    index, points, _ = _kept_points(folder, tile, has_normals, False)
    q = _normalized(points, center, exponent)
    rows = _native.nearest_rows(q, np.searchsorted(index, sample).astype(np.int64), min(neighbors, len(q)))
    return index[rows], q[rows]


def pooled_noise_estimate(found):
    """``estimate_noise()`` on the points of the tiles' ``tile_noise_neighbors``
    (each point once, in input order)."""
    from . import _unchecked_noise_estimate
    index = np.concatenate([f[0] for f in found])
    q = np.concatenate([f[1] for f in found])
    _, rows = np.unique(index, return_index=True)
    return _unchecked_noise_estimate(q[rows])


class _TileShape:
    """A tile's points and its job, the shape built (``conformal_alpha_shapes._job``).

    A future holds one on its worker between the closing values and the
    curvature. Moved to another worker or spilled, it travels as its tile and
    options only, and is built again by the task that uses it.
    """

    def __init__(self, folder, tile, has_normals, job, build=True):
        self.arguments = (folder, tile, has_normals, job)
        self.index, self.points, self.normals, self.is_core = tile_partition.load_tile(folder, tile, has_normals)
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


def tile_shape(folder, tile, has_normals, job):
    """A tile's shape, to be held on its worker."""
    return _TileShape(folder, tile, has_normals, job)


def tile_closing(folder, tile, has_normals, job, shape=None):
    """Writes the sorted local closing values of a tile's core points (of ``shape``,
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


def _object_votes(surface, objects, count, index, is_core, center):
    """What one run's orientation vote sums over an object's faces, per
    object (``objects``: per point, ``count`` of them), over the faces this tile counts (those
    whose vertex of least input index is a core point here, so that every
    face counts once), coordinates from ``center``: ``cone``, the faces'
    area normals dotted with a corner (six times the cones' volumes from
    ``center``, which the driver moves to the surface's center with
    ``normal``, their sum), ``cone_size`` (their sizes, from ``center``),
    ``up`` (the normals' z) and ``area`` (their lengths); and the sum and
    count of the surface vertices on core points (for that center)."""
    vertices, faces, point_index = surface["vertices"] - np.asarray(center), surface["faces"], surface["point_index"]
    corners = point_index[faces]
    counted = is_core[corners[np.arange(len(faces)), np.argmin(index[corners], axis=1)]]
    faces, of_face = faces[counted], objects[corners[counted, 0]]
    p0 = vertices[faces[:, 0]]
    normal = np.cross(vertices[faces[:, 1]] - p0, vertices[faces[:, 2]] - p0)
    cone = np.einsum("ij,ij->i", normal, p0)

    def summed(weights):
        return np.bincount(of_face, weights=weights, minlength=count).tolist()
    on_core = is_core[point_index]
    return {"cone": summed(cone), "normal": [summed(normal[:, k]) for k in range(3)],
            "cone_size": summed(np.abs(cone)), "up": summed(normal[:, 2]),
            "area": summed(np.linalg.norm(normal, axis=1)),
            "vertex_sum": vertices[on_core].sum(axis=0).tolist(), "vertex_count": int(on_core.sum())}


def tile_curvatures(folder, tile, has_normals, job, center, tree, shape=None):
    """A tile's curvature (of ``shape``, held on this worker, or of a shape
    built here): its part (core points), its seam file (halo points' normals,
    per scale) and what the driver needs (layer names, cone sums)."""
    from . import Result, _option_items
    started = time.monotonic()
    shape = shape if shape is not None else _TileShape(folder, tile, has_normals, job)
    index, points, is_core = shape.index, shape.points, shape.is_core
    native = shape.built()
    values = native.result(_option_items(job["tile_scales"], "scales"), None)
    result = Result(points, values)
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
        for key in curvature_file.SCALARS + ("source",):
            records[f"{key}_{name}"] = getattr(layer, key)[core]
    first_layers = [result[result.layers[s * per_scale]] for s in range(len(job["scales"]))]
    component = tile_partition.components(points, tile_partition.COMPONENT_CELL_SPACINGS * job["spacing"])
    inner = np.zeros(len(points), bool)
    inner_width = max(job["halo_spacings"] - tile_partition.JOINED_GAP_SPACINGS, 0.0) * job["spacing"]
    inner[tile_partition.assign(tree, points, inner_width)[tile]] = True
    objects = np.stack([tile_partition.surface_objects(component, surface, inner) for surface in values["surfaces"]])
    counts = (objects.max(axis=1) + 1).tolist()  # per scale, its objects' number
    tile_io.save_array(tile_partition.tile_path(folder, tile, "objects.npy"), objects[:, core])
    halo = np.flatnonzero(~is_core)
    seam = os.path.join(folder, "tiles", f"seam_{tile:05d}.npy")
    seam_records = np.empty(len(halo), [("index", "<i8"), ("owner", "<i4"),
                                        ("object", "<i4", (len(first_layers),)),
                                        ("normal", "<f4", (len(first_layers), 3))])
    seam_records["index"] = index[halo]
    seam_records["owner"] = tile_partition.owners(tree, points[halo])
    seam_records["object"] = objects[:, halo].T
    seam_records["normal"] = np.moveaxis(np.stack([layer.normal[halo].astype(np.float32) for layer in first_layers]),
                                         0, 1)
    tile_io.save_array(seam, seam_records)
    votes = [_object_votes(surface, of_points, count, index, is_core, center) for surface, of_points, count in
             zip(values["surfaces"], objects, counts)]
    # with input normals, per scale and object, how many of its core vertices' normals agree with them, of how many
    agreement = []
    if shape.normals is not None:
        for layer, of_points, count in zip(first_layers, objects, counts):
            own = core[layer.source[core] == 0]
            agree = np.einsum("ij,ij->i", layer.normal[own], shape.normals[own]) > 0
            agreement.append([np.bincount(of_points[own], weights=agree, minlength=count).astype(int).tolist(),
                              np.bincount(of_points[own], minlength=count).tolist()])
    part = tile_partition.part_path(folder, tile)
    tile_io.write_part(part, records, names, descriptions)
    sizes = [np.bincount(of_points[core], minlength=count).tolist() for of_points, count in zip(objects, counts)]
    return {"names": names, "descriptions": descriptions, "votes": votes, "agreement": agreement, "sizes": sizes,
            "size": os.path.getsize(part),
            "sha256": tile_io.file_digest(part), "seconds": time.monotonic() - started,
            "memory": _peak_memory(), "points": len(points), "core": len(core),
            "a": [layer.a for layer in first_layers]}
