"""Files of tiled runs (``conformal_alpha_shapes.tiles``): chunked readers of
large clouds, the tasks' arrays (``.npy``), the parts (binary PLY), the
manifest, and the merge into one ``curvatures.ply``; the tiles' point files
are ``tile_partition``'s.

Readers never hold the whole cloud: binary PLY and ``.npy`` are memory-mapped
and read in slices, ``.xyz`` is parsed a chunk of lines at a time, LAS is read
a range of records at a time by the program's reader (with the LiDAR
filters), and the merged LAS is written a chunk at a time. Every file
is written beside its final name and renamed into place (``os.replace``), so
a file under its final name is always complete, with the mode of any new
file (``output_files``).
"""

import hashlib
import json
import math
import mmap
import os

import numpy as np

from . import output_files
from .curvature_file import LAYER_FIELDS, SCALARS
from .matching import curvedness, shape_index

__all__ = [
    "InputError",
    "Cloud",
    "open_cloud",
    "atomic_write",
    "save_array",
    "part_dtype",
    "write_part",
    "read_part",
    "ply_header",
    "merge_parts",
    "merge_parts_las",
    "file_digest",
    "read_manifest",
    "write_manifest",
]


class InputError(ValueError):
    """Bad input, with the program's wording ("FILE:LINE: what")."""


_PLY_TYPES = {
    "char": "i1", "int8": "i1", "uchar": "u1", "uint8": "u1", "short": "i2", "int16": "i2",
    "ushort": "u2", "uint16": "u2", "int": "i4", "int32": "i4", "uint": "u4", "uint32": "u4",
    "float": "f4", "float32": "f4", "double": "f8", "float64": "f8",
}


class Cloud:
    """A point cloud read in chunks: ``count`` points, ``has_normals``, and
    ``chunks(size)`` yielding ``(start, points, normals)`` with (n, 3) float64
    arrays (normals None without them). A LAS cloud has ``las`` (its header,
    a dict), ``las_filter`` and ``las_counts`` (what the filters kept) and
    ``las_fields(size)`` yielding ``(start, fields)`` in the same order."""

    def __init__(self, path, count, has_normals, reader):
        self.path = path
        self.count = count
        self.has_normals = has_normals
        self._reader = reader
        self.las = None
        self.las_filter = None
        self.las_counts = None
        self.las_fields = None

    def chunks(self, size):
        """The cloud in order, ``size`` points at a time."""
        return self._reader(size)


def _structured_reader(records, names):
    """Chunks of the fields x y z (and nx ny nz) of a structured array (a memory map)."""
    normal_names = ("nx", "ny", "nz")
    has_normals = all(name in names for name in normal_names)

    def chunks(size):
        for start in range(0, len(records), size):
            block = records[start:start + size]
            yield start, _columns(block, "xyz"), _columns(block, normal_names) if has_normals else None
    return has_normals, chunks


def _columns(block, names):
    """The fields ``names`` of a structured array as columns of a float64
    array, filled one at a time (no temporary array per field)."""
    out = np.empty((len(block), len(names)))
    for k, name in enumerate(names):
        out[:, k] = block[name]
    return out


def _open_ply(path):
    with open(path, "rb") as f:
        if f.readline().strip() != b"ply":
            raise InputError(f"{path}:1: not a PLY file")
        fmt, elements, line_number = None, [], 1
        while True:
            line = f.readline()
            line_number += 1
            if not line:
                raise InputError(f"{path}: the PLY header has no end_header")
            words = line.decode("ascii", "replace").split()
            if not words or words[0] in ("comment", "obj_info"):
                continue
            if words[0] == "end_header":
                break
            if words[0] == "format":
                fmt = words[1]
            elif words[0] == "element":
                elements.append([words[1], int(words[2]), []])
            elif words[0] == "property":
                if not elements:
                    raise InputError(f"{path}:{line_number}: a property before any element")
                if words[1] == "list":
                    if elements[-1][0] == "vertex":
                        raise InputError(f"{path}:{line_number}: a list property of vertices is not read in tiles")
                    elements[-1][2].append(None)
                    continue
                if words[1] not in _PLY_TYPES:
                    raise InputError(f"{path}:{line_number}: unknown PLY type '{words[1]}'")
                elements[-1][2].append((words[2], _PLY_TYPES[words[1]]))
        offset = f.tell()
    if fmt not in ("binary_little_endian", "binary_big_endian"):
        raise InputError(f"{path}: tiled runs read binary PLY (format {fmt}); "
                         "convert it, or give .npy or .xyz")
    order = "<" if fmt == "binary_little_endian" else ">"
    for name, count, properties in elements:
        if name == "vertex":
            names = [p[0] for p in properties]
            if not all(c in names for c in "xyz"):
                raise InputError(f"{path}: the vertices have no x, y and z")
            dtype = np.dtype([(p[0], order + p[1]) for p in properties])
            records = np.memmap(path, dtype=dtype, mode="r", offset=offset, shape=(count,)) if count else \
                np.empty(0, dtype)
            has_normals, reader = _structured_reader(records, names)
            return Cloud(path, count, has_normals, reader)
        if any(p is None for p in properties):
            raise InputError(f"{path}: element {name} before the vertices has list properties")
        offset += count * np.dtype([(p[0], order + p[1]) for p in properties]).itemsize
    raise InputError(f"{path}: no vertex element")


def _open_npy(path):
    array = np.load(path, mmap_mode="r")
    if array.ndim != 2 or array.shape[1] not in (3, 6) or array.dtype.kind not in "fiu":
        raise InputError(f"{path}: expected an (N, 3) or (N, 6) array of numbers, got {array.shape} {array.dtype}")

    def chunks(size):
        for start in range(0, len(array), size):
            block = np.asarray(array[start:start + size], dtype=np.float64)
            yield start, np.ascontiguousarray(block[:, :3]), \
                (np.ascontiguousarray(block[:, 3:]) if array.shape[1] == 6 else None)
    return Cloud(path, len(array), array.shape[1] == 6, chunks)


def _xyz_rows(path, lines, first_line, columns):
    """The numbers of ``lines`` (text, ``columns`` per line); the program's message on a bad line."""
    try:
        rows = np.loadtxt(lines, dtype=np.float64, ndmin=2, comments="#")
        if rows.shape[1] == columns:
            return rows
    except ValueError:
        pass
    rows = []
    for k, line in enumerate(lines):
        fields = line.split("#")[0].split()
        if not fields:
            continue
        if len(fields) != columns:
            raise InputError(f"{path}:{first_line + k}: expected {columns} numbers as on line 1, "
                             f"found {len(fields)} fields")
        values = []
        for field in fields:
            try:
                values.append(float(field))
            except ValueError:
                raise InputError(f"{path}:{first_line + k}: not a number: '{field}'") from None
        rows.append(values)
    return np.array(rows, dtype=np.float64).reshape(-1, columns)


def _open_xyz(path):
    with open(path) as f:
        first = ""
        for first in f:
            if first.split("#")[0].split():
                break
    columns = len(first.split("#")[0].split())
    if columns not in (3, 6):
        raise InputError(f"{path}:1: expected 3 or 6 numbers per line (x y z [nx ny nz]), found {columns} fields")

    def chunks(size):
        start = 0
        with open(path) as f:
            line_number = 1
            while True:
                lines = [line for _, line in zip(range(size), f)]
                if not lines:
                    return
                rows = _xyz_rows(path, lines, line_number, columns)
                bad = np.flatnonzero(~np.isfinite(rows).all(axis=1))
                if len(bad):
                    k = int(bad[0])
                    field = next(x for x in lines[k].split() if not math.isfinite(float(x)))
                    raise InputError(f"{path}:{line_number + k}: coordinate is NaN or infinite: '{field}'")
                line_number += len(lines)
                if len(rows):
                    yield start, np.ascontiguousarray(rows[:, :3]), \
                        (np.ascontiguousarray(rows[:, 3:]) if columns == 6 else None)
                start += len(rows)

    count = sum(len(p) for _, p, _ in chunks(1 << 20))
    return Cloud(path, count, columns == 6, chunks)


# LAS records read at a time at most: a chunk's points and fields take about 100 bytes each.
LAS_CHUNK = 1 << 20
# Points read at a time where the chunks' size changes no value.
READ_CHUNK = 1 << 18
# Records of the parts merged at a time: written at scattered input indices,
# each may touch a page of its own (4 kB), which the driver holds until the block is done.
MERGE_CHUNK = 1 << 12
# LAS records of the merged file made at a time (the values in double, about 3 kB each with five layers).
LAS_RECORDS_MADE = 1 << 13
# LAS records read by one call of the native reader (about 100 bytes each as it reads them).
LAS_READ = 1 << 16


def _open_las(path, las_filter):
    """A LAS file read a range of records at a time (``las_filter``: the
    keywords classes, drop_withheld, returns of ``read_point_cloud``)."""
    from . import _native
    classes = [str(c) for c in las_filter.get("classes", ())]
    drop, returns = bool(las_filter.get("drop_withheld", False)), las_filter.get("returns", "all")

    def read(first, size, with_fields):
        try:
            return _native.read_las_chunk(path, first, size, classes, drop, returns, with_fields)
        except ValueError as e:
            raise InputError(str(e)) from None

    head = read(0, 0, False)
    total = head["las"]["number_of_points"]

    def kept_chunks(size, with_fields):
        start = 0
        for first in range(0, total, size):
            chunk = read(first, size, with_fields)
            yield start, chunk
            start += len(chunk["points"])

    counts = {"read": 0, "classes": 0, "withheld": 0, "returns": 0}
    for _, chunk in kept_chunks(min(LAS_READ, LAS_CHUNK), False):
        for key in counts:
            counts[key] += chunk["counts"][key]

    def chunks(size):
        # a chunk's points gathered from smaller reads: the reader's records
        # weigh about four times the points
        size = min(max(size, 1), LAS_CHUNK)
        start = 0
        for first in range(0, total, size):
            last = min(first + size, total)
            points, kept = np.empty((last - first, 3)), 0
            for at in range(first, last, LAS_READ):
                piece = read(at, min(LAS_READ, last - at), False)["points"]
                points[kept:kept + len(piece)] = piece
                kept += len(piece)
            if kept:
                yield start, points[:kept], None
            start += kept

    def fields(size):
        for start, chunk in kept_chunks(min(max(size, 1), LAS_CHUNK), True):
            if len(chunk["points"]):
                yield start, chunk["fields"]

    cloud = Cloud(path, counts["returns"], False, chunks)
    cloud.las = head["las"]
    cloud.las_filter = {"classes": [int(c) for c in classes], "drop_withheld": drop, "returns": returns}
    cloud.las_counts = counts
    cloud.las_fields = fields
    return cloud


def open_cloud(path, las_filter=None):
    """The cloud at ``path`` (binary PLY, ``.npy``, ``.xyz``, ``.las``), checked to the end.

    ``las_filter``: for LAS, a dict of the keywords classes, drop_withheld
    and returns of ``read_point_cloud`` (the points the filters keep are
    the cloud). Raises ``InputError`` with the program's wording: a missing
    file, a bad line of a ``.xyz`` (file and line), a bad LAS file, a NaN or
    infinite coordinate.
    """
    path = os.fspath(path)
    if not os.path.exists(path):
        raise InputError(f"{path}: no such file")
    extension = os.path.splitext(path)[1].lower()
    las_filter = las_filter or {}
    active = bool(las_filter.get("classes")) or las_filter.get("drop_withheld") or \
        las_filter.get("returns", "all") != "all"
    if active and extension not in (".las", ".laz"):
        raise InputError(f"{path}: classes, drop_withheld and returns filter LAS input (.las)")
    if extension == ".laz":
        from . import _native
        try:
            _native.read_point_cloud(path, [], False, "all")  # refuses it, saying how to decompress it
        except ValueError as e:
            raise InputError(str(e)) from None
    openers = {".ply": _open_ply, ".npy": _open_npy, ".xyz": _open_xyz,
               ".las": lambda p: _open_las(p, las_filter)}
    if extension not in openers:
        raise InputError(f"{path}: tiled runs read .ply (binary), .npy, .xyz and .las, not '{extension}'")
    cloud = openers[extension](path)
    for start, points, _ in cloud.chunks(READ_CHUNK):
        bad = np.flatnonzero(~np.isfinite(points).all(axis=1))
        if len(bad):
            raise InputError(f"{path}: point {start + int(bad[0])}: coordinate is NaN or infinite")
    if cloud.count < 4:
        raise InputError(f"{path}: {cloud.count} points; at least 4 that span 3D are needed")
    return cloud


def atomic_write(path, write):
    """Calls ``write(temporary_path)`` and renames the file to ``path``: never half written
    (``output_files.atomic_write``: the mode of any new file, errors naming ``path``)."""
    output_files.atomic_write(path, write)


def save_array(path, values):
    """Writes a numpy array as ``.npy``, atomically."""
    def write(temporary):
        with open(temporary, "wb") as f:
            np.save(f, values)
    atomic_write(path, write)


def part_dtype(layers, with_index=True):
    """The record of ``curvatures.ply`` for layer names ``layers`` (plus ``input_index``); the
    merged file's (``with_index=False``) has each layer's shape index and curvedness after the layers."""
    fields = [("x", "<f8"), ("y", "<f8"), ("z", "<f8"), ("outlier", "u1")]
    for name in layers:
        fields += [(f"{field}_{name}", "<f4") for field in LAYER_FIELDS] + [(f"source_{name}", "u1")]
    if not with_index:
        for name in layers:
            fields += [(f"shape_index_{name}", "<f4"), (f"curvedness_{name}", "<f4")]
    if with_index:
        fields.append(("input_index", "<f8"))
    return np.dtype(fields)


def ply_header(layers, descriptions, count, with_index=True):
    """The header of the program's ``curvatures.ply`` (and of a part, with ``input_index``)."""
    types = {"<f8": "double", "<f4": "float", "u1": "uchar", "|u1": "uchar"}
    lines = ["ply", "format binary_little_endian 1.0",
             "comment conformal_curvature: values per input point, in input units",
             "comment source_L: 0 own surface vertex, 1 nearest surface point, 2 no value"]
    lines += [f"comment layer {name}: {descriptions[name]}" for name in layers]
    lines.append(f"element vertex {count}")
    dtype = part_dtype(layers, with_index)
    lines += [f"property {types[dtype.fields[name][0].str]} {name}" for name in dtype.names]
    lines.append("end_header")
    return ("\n".join(lines) + "\n").encode("ascii")


def write_part(path, records, layers, descriptions):
    """Writes ``records`` (of ``part_dtype(layers)``) as a binary PLY part, atomically."""
    def write(temporary):
        with open(temporary, "wb") as f:
            f.write(ply_header(layers, descriptions, len(records)))
            records.tofile(f)
    atomic_write(path, write)


def part_header(path):
    """A part's PLY header, as bytes (its records follow it)."""
    with open(path, "rb") as f:
        head = f.read(1 << 16)
    return head[:head.index(b"end_header\n") + len(b"end_header\n")]


def read_part(path, layers):
    """A part's records (a memory map of ``part_dtype(layers)``)."""
    return np.memmap(path, dtype=part_dtype(layers), mode="r", offset=len(part_header(path)))


def _mapped_records(path, dtype, offset, writable=False):
    """The records of ``dtype`` from ``offset`` to the end of the file ``path``,
    mapped into memory, and the mapping: its ``madvise(mmap.MADV_DONTNEED)``
    lets go of the pages touched so far (the kernel's cache keeps them, and
    writes back those written), so that the process's memory does not grow
    with the file as it goes through it."""
    with open(path, "r+b" if writable else "rb") as f:
        mapping = mmap.mmap(f.fileno(), 0, access=mmap.ACCESS_WRITE if writable else mmap.ACCESS_READ)
    return np.frombuffer(mapping, dtype, offset=offset), mapping


def merge_parts(path, part_paths, layers, descriptions, count):
    """One ``curvatures.ply`` of ``count`` points in input order from the parts
    (the program's fields; each part's records go to their input indices)."""
    dtype = part_dtype(layers, with_index=False)
    header = ply_header(layers, descriptions, count, with_index=False)

    def write(temporary):
        with open(temporary, "wb") as f:
            f.write(header)
            f.truncate(len(header) + count * dtype.itemsize)
        out, mapping = _mapped_records(temporary, dtype, len(header), writable=True)
        for part_path in part_paths:
            part, part_mapping = _mapped_records(part_path, part_dtype(layers), len(part_header(part_path)))
            for start in range(0, len(part), MERGE_CHUNK):
                block = part[start:start + MERGE_CHUNK]
                values = np.empty(len(block), dtype)
                for name in block.dtype.names:
                    if name != "input_index":
                        values[name] = block[name]
                # computed here, once the parts' orientations are final
                for name in layers:
                    k1, k2 = block[f"k1_{name}"].astype(np.float64), block[f"k2_{name}"].astype(np.float64)
                    values[f"shape_index_{name}"] = shape_index(k1, k2)
                    values[f"curvedness_{name}"] = curvedness(k1, k2)
                out[block["input_index"].astype(np.int64)] = values
                mapping.madvise(mmap.MADV_DONTNEED)  # a block's records lie anywhere in the file
                part_mapping.madvise(mmap.MADV_DONTNEED)
        del out
        mapping.flush()
        mapping.close()
    atomic_write(path, write)


def merge_parts_las(path, merged_ply, layers, cloud):
    """``path``: the merged ``curvatures.ply`` (``merged_ply``, in input
    order) as LAS 1.4, a chunk at a time: the LAS input's records (its
    scaled integers, fields and extra bytes) and CRS records, else the
    points at a power-of-ten scale; the layers' values as named extra bytes
    (as ``Result.write_las``)."""
    from . import _native
    records, mapping = _mapped_records(merged_ply, part_dtype(layers, with_index=False), len(part_header(merged_ply)))
    count = len(records)
    if cloud.las is not None:
        info = dict(cloud.las)
        field_chunks = cloud.las_fields(LAS_RECORDS_MADE)
    else:
        low, high = np.full(3, np.inf), np.full(3, -np.inf)
        for start in range(0, count, READ_CHUNK):
            block = records[start:start + READ_CHUNK]
            for k, axis in enumerate("xyz"):
                low[k] = min(low[k], float(block[axis].min()))
                high[k] = max(high[k], float(block[axis].max()))
            mapping.madvise(mmap.MADV_DONTNEED)
        scale, offset = _native.las_scale(list(low), list(high))
        info = {"scale": scale, "offset": offset, "rgb": False}
        field_chunks = ((start, None) for start in range(0, count, LAS_CHUNK))
    low = np.full(3, np.iinfo(np.int64).max)
    high = np.full(3, np.iinfo(np.int64).min)
    by_return = np.zeros(15, np.uint64)

    def layer_arrays(block, name):
        values = {"name": name, "description": ""}
        for key, fields in (("normal", ("nx", "ny", "nz")), ("d1", ("d1x", "d1y", "d1z")),
                            ("d2", ("d2x", "d2y", "d2z"))):
            values[key] = np.column_stack([block[f"{f}_{name}"] for f in fields]).astype(np.float64)
        for key in SCALARS:
            values[key] = block[f"{key}_{name}"].astype(np.float64)
        values["source"] = np.ascontiguousarray(block[f"source_{name}"])
        return values

    def write(temporary):
        nonlocal low, high, by_return
        header_size = len(_native.las_header(info, list(layers), 0, [0] * 3, [0] * 3, [0] * 15)[0])
        with open(temporary, "wb") as f:
            f.write(b"\0" * header_size)
            written = 0
            for start, fields in field_chunks:
                n = len(fields["X"]) if fields is not None else min(LAS_CHUNK, count - start)
                for first in range(0, n, LAS_RECORDS_MADE):
                    size = min(LAS_RECORDS_MADE, n - first)
                    block = records[start + first:start + first + size]
                    points = np.column_stack([block[axis] for axis in "xyz"]).astype(np.float64)
                    part = None if fields is None else {key: values[first:first + size]
                                                        for key, values in fields.items()}
                    data, stats = _native.las_records(points, block["outlier"].astype(bool),
                                                      [layer_arrays(block, name) for name in layers], part, info)
                    f.write(data)
                    mapping.madvise(mmap.MADV_DONTNEED)
                    low = np.minimum(low, stats["min"])
                    high = np.maximum(high, stats["max"])
                    by_return += np.array(stats["by_return"], np.uint64)
                written += n
            if written != count:
                raise InputError(f"{cloud.path}: the input changed during the run ({written} points, "
                                 f"the parts hold {count})")
            header, evlrs = _native.las_header(info, list(layers), count, [int(x) for x in low],
                                               [int(x) for x in high], [int(x) for x in by_return])
            f.write(evlrs)
            f.seek(0)
            f.write(header)
    atomic_write(path, write)


def file_digest(path):
    """The SHA-256 of a file's bytes (hex)."""
    digest = hashlib.sha256()
    with open(path, "rb") as f:
        for block in iter(lambda: f.read(1 << 22), b""):
            digest.update(block)
    return digest.hexdigest()


def read_manifest(path):
    """The manifest at ``path`` (a dict), or None when there is none or it is unreadable."""
    try:
        with open(path) as f:
            return json.load(f)
    except (OSError, ValueError):
        return None


def write_manifest(path, manifest):
    """Writes the manifest (or any dict) as JSON, atomically."""
    def write(temporary):
        with open(temporary, "w") as f:
            json.dump(manifest, f, indent=1, sort_keys=True)
    atomic_write(path, write)
