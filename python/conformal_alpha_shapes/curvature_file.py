"""The point cloud file ``curvatures.ply`` (the program's, ``Result.write_ply``'s,
a tiled run's merged file or parts) read back into the values of a
``Result``, and written with double values and the run's decisions, for an
exact round trip.

The program's file holds per point x y z (double), outlier (uchar) and per
layer L the floats nx_L ny_L nz_L H_L K_L k1_L k2_L d1x_L .. d2z_L radius_L
distance_L and the uchar source_L, with a comment line per layer
("comment layer L: a = ... (scale), neighborhood"). The double file has the
same properties as doubles and one more comment line, ``comment
conformal_alpha_shapes result {JSON}``: the spacing, the noise, whether the
points were smoothed, the number of merged copies, and per layer its exact
scale ``a`` and surface report.
"""

import json
import os

import numpy as np

from . import output_files
from .matching import curvedness, shape_index

__all__ = ["read_values", "write_double_ply", "LAYER_FIELDS", "SCALARS"]

LAYER_FIELDS = ("nx", "ny", "nz", "H", "K", "k1", "k2", "d1x", "d1y", "d1z", "d2x", "d2y", "d2z",
                "radius", "distance", "H_sigma", "K_sigma", "normal_sigma", "H_noise_sigma")
_TRIPLES = {"normal": ("nx", "ny", "nz"), "d1": ("d1x", "d1y", "d1z"), "d2": ("d2x", "d2y", "d2z")}
SCALARS = ("H", "K", "k1", "k2", "radius", "distance", "H_sigma", "K_sigma", "normal_sigma", "H_noise_sigma")
_OPTIONAL = ("H_sigma", "K_sigma", "normal_sigma", "H_noise_sigma")
_RESULT_COMMENT = "conformal_alpha_shapes result "
_PLY_TYPES = {
    "char": "i1", "int8": "i1", "uchar": "u1", "uint8": "u1", "short": "i2", "int16": "i2",
    "ushort": "u2", "uint16": "u2", "int": "i4", "int32": "i4", "uint": "u4", "uint32": "u4",
    "float": "f4", "float32": "f4", "double": "f8", "float64": "f8",
}
_HEADER_COMMENTS = ("conformal_curvature: values per input point, in input units",
                    "source_L: 0 own surface vertex, 1 nearest surface point, 2 no value")


def _read_header(path):
    """(format, comments, [(element, count, [(property, dtype or None for a list)])], bytes of the header)."""
    with open(path, "rb") as f:
        if f.readline().rstrip(b"\r\n") != b"ply":
            raise ValueError(f"{path}: not a PLY file")
        fmt, comments, elements = None, [], []
        while True:
            line = f.readline()
            if not line:
                raise ValueError(f"{path}: the PLY header has no end_header")
            text = line.decode("utf-8", "replace").rstrip("\r\n")
            words = text.split()
            if not words:
                continue
            if words[0] == "end_header":
                return fmt, comments, elements, f.tell()
            if words[0] == "comment":
                comments.append(text[len("comment "):])
            elif words[0] == "format":
                fmt = words[1] if len(words) > 1 else None
            elif words[0] == "element" and len(words) == 3:
                elements.append((words[1], int(words[2]), []))
            elif words[0] == "property" and elements:
                if words[1] == "list":
                    elements[-1][2].append((words[-1], None))
                elif words[1] in _PLY_TYPES and len(words) == 3:
                    elements[-1][2].append((words[2], _PLY_TYPES[words[1]]))
                else:
                    raise ValueError(f"{path}: unknown PLY property line '{text}'")


def read_values(path):
    """The values of a ``curvatures.ply`` as ``Result`` takes them: (points, dict).

    Raises ValueError naming the path when the file is not such a point
    cloud (not binary PLY, no vertex element first, no x y z, a layer's
    property missing).
    """
    path = os.fspath(path)
    fmt, comments, elements, offset = _read_header(path)
    if fmt not in ("binary_little_endian", "binary_big_endian"):
        raise ValueError(f"{path}: not a curvatures.ply: the format is {fmt}, not binary PLY")
    if not elements or elements[0][0] != "vertex" or any(name == "face" for name, _, _ in elements):
        raise ValueError(f"{path}: not a curvatures.ply: expected one vertex element (a point cloud), "
                         f"found {', '.join(name for name, _, _ in elements) or 'none'}")
    _, count, properties = elements[0]
    if any(dtype is None for _, dtype in properties):
        raise ValueError(f"{path}: not a curvatures.ply: the vertices have a list property")
    order = "<" if fmt == "binary_little_endian" else ">"
    dtype = np.dtype([(name, order + t) for name, t in properties])
    names = set(dtype.names)
    missing = [axis for axis in "xyz" if axis not in names]
    if missing:
        raise ValueError(f"{path}: not a curvatures.ply: the vertices have no {' '.join(missing)}")
    with open(path, "rb") as f:
        f.seek(offset)
        records = np.fromfile(f, dtype=dtype, count=count)
    if len(records) != count:
        raise ValueError(f"{path}: the file ends after {len(records)} of its {count} points")

    described = {}
    run = {}
    for comment in comments:
        if comment.startswith("layer ") and ": " in comment:
            label, description = comment[len("layer "):].split(": ", 1)
            described[label] = description
        elif comment.startswith(_RESULT_COMMENT):
            try:
                run = json.loads(comment[len(_RESULT_COMMENT):])
            except ValueError:
                raise ValueError(f"{path}: its conformal_alpha_shapes comment is not readable") from None
    labels = list(described) or [name[len("source_"):] for name in dtype.names if name.startswith("source_")]
    layers = []
    for label in labels:
        # files written before the uncertainties were added have none: NaN
        wanted = [f"{field}_{label}" for field in LAYER_FIELDS if field not in _OPTIONAL] + [f"source_{label}"]
        absent = [name for name in wanted if name not in names]
        if absent:
            raise ValueError(f"{path}: layer {label} has no {', '.join(absent)}")
        values = {key: np.stack([records[f"{field}_{label}"] for field in fields], axis=1).astype(np.float64)
                  for key, fields in _TRIPLES.items()}
        for key in SCALARS:
            name = f"{key}_{label}"
            values[key] = records[name].astype(np.float64) if name in names else np.full(count, np.nan)
        values["source"] = records[f"source_{label}"].astype(np.uint8)
        values["name"] = label
        values["description"] = described.get(label)
        exact = run.get("layers", {}).get(label, {})
        values["a"] = exact["a"] if "a" in exact else _scale_of(values["description"])
        values["surface"] = exact.get("surface")
        layers.append(values)
    points = np.stack([records[axis] for axis in "xyz"], axis=1).astype(np.float64)
    outlier = (records["outlier"] != 0) if "outlier" in names else np.zeros(count, dtype=bool)
    return points, {"layers": layers, "outlier": outlier, "spacing": run.get("spacing"),
                    "noise": run.get("noise"), "denoised": run.get("denoised"), "merged": run.get("merged")}


def _scale_of(description):
    """The scale ``a`` of a layer's description ("a = 0.0123 (auto), ..."), as printed; None without one."""
    if description and description.startswith("a = "):
        try:
            return float(description[len("a = "):].split()[0].rstrip(","))
        except ValueError:
            return None
    return None


def write_double_ply(path, points, outlier, layers, spacing, noise, denoised, merged):
    """Writes the properties of ``curvatures.ply`` as doubles, with the run's decisions in a comment.

    ``layers``: the ``Layer`` objects, in order. Atomic, with a new file's mode.
    """
    count = len(points)
    for layer in layers:
        for key, shape in [(key, (count, 3)) for key in _TRIPLES] + [(key, (count,)) for key in SCALARS + ("source",)]:
            if np.shape(getattr(layer, key)) != shape:
                raise ValueError(f"write_ply: layer {layer.name}: {key} has not one value per point")
    fields = [("x", "<f8"), ("y", "<f8"), ("z", "<f8"), ("outlier", "u1")]
    for layer in layers:
        fields += [(f"{field}_{layer.name}", "<f8") for field in LAYER_FIELDS] + [(f"source_{layer.name}", "u1")]
    # after the layers, as in the program's file
    for layer in layers:
        fields += [(f"shape_index_{layer.name}", "<f8"), (f"curvedness_{layer.name}", "<f8")]
    records = np.empty(count, dtype=fields)
    for i, axis in enumerate("xyz"):
        records[axis] = points[:, i]
    records["outlier"] = outlier
    for layer in layers:
        for key, triple in _TRIPLES.items():
            for i, field in enumerate(triple):
                records[f"{field}_{layer.name}"] = getattr(layer, key)[:, i]
        for key in SCALARS:
            records[f"{key}_{layer.name}"] = getattr(layer, key)
        records[f"source_{layer.name}"] = layer.source
        records[f"shape_index_{layer.name}"] = shape_index(layer.k1, layer.k2)
        records[f"curvedness_{layer.name}"] = curvedness(layer.k1, layer.k2)
    run = {"spacing": spacing, "noise": noise, "denoised": denoised, "merged": merged,
           "layers": {layer.name: {"a": layer.a, "surface": layer.surface} for layer in layers}}
    lines = ["ply", "format binary_little_endian 1.0"] + [f"comment {c}" for c in _HEADER_COMMENTS]
    lines += [f"comment layer {layer.name}: {layer.description}" for layer in layers]
    lines.append("comment " + _RESULT_COMMENT + json.dumps(run, sort_keys=True))
    lines.append(f"element vertex {len(points)}")
    lines += [f"property {'double' if t == '<f8' else 'uchar'} {name}" for name, t in fields]
    lines.append("end_header")
    header = ("\n".join(lines) + "\n").encode("utf-8")

    def write(temporary):
        with open(temporary, "wb") as f:
            f.write(header)
            records.tofile(f)
    output_files.atomic_write(path, write)
