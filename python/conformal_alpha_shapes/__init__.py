"""Conformal alpha shapes and multi-scale curvature of 3D point clouds.

The package of the CGAL package Conformal_alpha_shapes_3, for numpy:

- ``multiscale_curvatures(points)``: the whole job of the ``conformal_curvature``
  program, per input point: normal, mean and Gaussian curvature (H, K),
  principal curvatures and directions (k1, k2, d1, d2), at several scales.
- ``ConformalAlphaShape(points)``: the filtration, its spectrum, its scale
  suggestion and its surfaces as (vertices, faces) arrays.
- ``vertex_curvatures(vertices, faces)``: curvature of a triangle mesh.
- ``estimate_noise(points)``, ``denoise(points)``, ``read_point_cloud(path)``
  (.xyz, .pwn, .ply, .off, .obj and LAS, with LiDAR filters); ``Result.write_ply``
  and ``Result.write_las`` write the values per point.
- ``read_curvatures(path)``: a ``curvatures.ply`` back into a ``Result``.
- ``region_descriptors(points, result, centers)`` and ``match_regions(a, b)``:
  multi-scale curvature descriptors of surface regions, the best matches of
  one surface's regions on another, and the registration they give.
- ``front_closing_values(points)``: the front's share of the automatic scale,
  per point, for tiled runs (``conformal_alpha_shapes.tiles``).

Arrays are numpy arrays: points are (N, 3), float64 (other real dtypes and
non-contiguous arrays are converted). Lengths and curvatures are in the
units of the points. The computations release the GIL, report their
progress to an optional ``progress(stage, fraction)`` callable and stop
with ``KeyboardInterrupt`` on Ctrl-C. The objects pickle (a
``ConformalAlphaShape`` is rebuilt from its points), so that they travel to
Dask's workers.

Open3D, pandas and others, without depending on them::

    points = np.asarray(pcd.points)                  # an open3d.geometry.PointCloud
    r = cas.multiscale_curvatures(points, np.asarray(pcd.normals) if pcd.has_normals() else None)
    pcd.normals = o3d.utility.Vector3dVector(r["r4s"].normal)
    pcd.colors = o3d.utility.Vector3dVector(r["r4s"].colors("H"))
    vertices, faces, _ = cas.ConformalAlphaShape(points).surface()
    mesh = o3d.geometry.TriangleMesh(o3d.utility.Vector3dVector(vertices), o3d.utility.Vector3iVector(faces))
    r.to_dataframe("r4s")                            # pandas; r.to_structured("r4s") for numpy
"""

import numbers
import os
import warnings

import numpy as np

from . import _native, curvature_file
from .matching import (Matches, Regions, curvedness, farthest_point_sample, histogram_distances, match_regions,
                       region_descriptors, shape_index)
from .output_files import atomic_write

__version__ = _native.__version__

__all__ = [
    "ConformalAlphaShape",
    "Layer",
    "Matches",
    "Regions",
    "curvedness",
    "farthest_point_sample",
    "histogram_distances",
    "match_regions",
    "region_descriptors",
    "shape_index",
    "NoiseEstimate",
    "PointCloud",
    "Result",
    "denoise",
    "estimate_noise",
    "front_closing_values",
    "multiscale_curvatures",
    "read_curvatures",
    "read_point_cloud",
    "vertex_curvatures",
]

# estimate_noise() fits a cubic to each sampled point's 24 nearest neighbors
_NOISE_POINTS = 25


def _real_array(values, name):
    array = values if isinstance(values, np.ndarray) else np.asarray(values)
    if array.dtype.kind not in "fiu":
        raise TypeError(f"{name} must be an array of real numbers, got dtype {array.dtype}")
    return array


def _triples(values, name, rows="N"):
    """An (n, 3) float64 C-contiguous array; no copy when `values` is one."""
    array = _real_array(values, name)
    if array.ndim != 2 or array.shape[1] != 3:
        raise ValueError(f"{name} must be an ({rows}, 3) array, got shape {array.shape}")
    return np.ascontiguousarray(array, dtype=np.float64)


def _option_items(values, name, integers=False):
    """The items of a list option as the program spells them ("auto", "25%", "4s", numbers)."""
    if isinstance(values, (str, numbers.Number)):
        values = (values,)
    allowed = numbers.Integral if integers else (str, numbers.Real)
    items = []
    for value in values:
        if isinstance(value, bool) or not isinstance(value, allowed):
            raise TypeError(f"{name} must hold {'ints' if integers else 'strings or numbers'}, got {value!r}")
        if isinstance(value, str):
            if "," in value:
                raise ValueError(f"{name}: one value per item, got {value!r}")
            items.append(value)
        elif isinstance(value, numbers.Integral):
            items.append(str(int(value)))
        else:
            items.append(repr(float(value)))
    return items


def _choice(value, name):
    if not isinstance(value, str):
        raise TypeError(f"{name} must be a string, got {value!r}")
    return value


def _threads(threads):
    if threads is None:
        return 0
    if isinstance(threads, bool) or not isinstance(threads, numbers.Integral):
        raise TypeError(f"threads must be an int or None, got {threads!r}")
    if threads < 1:
        raise ValueError(f"threads must be >= 1, or None for all, got {threads}")
    return int(threads)


def _arrays_equal(a, b):
    """Whether two arrays (or Nones) are the same to the bit: dtype, shape and bytes (NaN included)."""
    if a is None or b is None:
        return a is None and b is None
    a, b = np.asarray(a), np.asarray(b)
    return a.dtype == b.dtype and a.shape == b.shape and a.tobytes() == b.tobytes()


def _same_number(a, b):
    """Equality of numbers, NaN equal to NaN (None only to None)."""
    if a is None or b is None:
        return a is None and b is None
    return a == b or (a != a and b != b)


def _points_text(n):
    return f"{n} point" if n == 1 else f"{n} points"


def _same_report(a, b):
    """Equality of surface reports (dicts of numbers, NaN equal to NaN) or Nones."""
    if a is None or b is None:
        return a is None and b is None
    return a.keys() == b.keys() and all(_same_number(a[key], b[key]) for key in a)


def _check_shape_points(function, points):
    if len(points) < 4:
        raise ValueError(f"{function}: {_points_text(len(points))}; at least 4 that are not coplanar are needed "
                         "(the shape is built on their 3D Delaunay triangulation)")


def _check_noise_points(function, points):
    if len(points) < _NOISE_POINTS:
        raise ValueError(f"{function}: {_points_text(len(points))}; at least {_NOISE_POINTS} are needed (the noise and "
                         f"the sample spacing are estimated from each point's {_NOISE_POINTS - 1} nearest neighbors)")


def _check_scale(function, a):
    """``a`` as a float, checked: a scale is a number >= 0 (infinity included)."""
    if isinstance(a, bool) or not isinstance(a, numbers.Real):
        raise TypeError(f"{function}: the scale a must be a number, got {a!r}")
    a = float(a)
    if not a >= 0:
        raise ValueError(f"{function}: the scale a must be >= 0, got {a}")
    return a


class Layer:
    """The curvature of every point (or mesh vertex) for one scale and neighborhood.

    Attributes (arrays of length N, the number of points):
        normal, d1, d2: (N, 3) float64, the unit normal and principal
            directions (d1 of k1, d2 of k2).
        H, K, k1, k2: (N,) float64, mean and Gaussian curvature and the
            principal curvatures (k1 >= k2), in inverse units of the points;
            H > 0 where the surface bends away from its normal (a sphere with
            outward normals has H = 1/r).
        shape_index, curvedness: (N,) float64, Koenderink's shape index in
            [-1, 1] (+1 on caps, -1 on cups, 0 on symmetric saddles, NaN
            where flat) and curvedness (inverse units), from k1 and k2
            (computed when read; ``shape_index()`` tells the convention).
        radius: (N,) float64, the radius of the fit's neighborhood.
        source: (N,) uint8, where a point's values come from: 0 its own
            surface vertex, 1 the nearest surface point, 2 no value (NaN).
            Only for point layers (``None`` for a mesh).
        distance: (N,) float64, from the point to the surface point whose
            values it took (0 on its own vertex). Point layers only.
        H_sigma, K_sigma, normal_sigma: (N,) float64, the standard
            uncertainties of H and K (same units) and of the normal's
            direction (degrees): from the fit's residuals, its neighbors, the
            sample's noise and the bias of its radius, grown with
            ``distance`` (the manual, section "Uncertainty"); NaN where
            unknown. ``np.abs(layer.H) > 2 * layer.H_sigma`` keeps the values
            that their uncertainty does not swamp.
        H_noise_sigma: (N,) float64, the part of H_sigma that the points'
            noise gives (the rest is the bias of the radius); None in a
            result read from a file without it.
        name: the layer's name, as the program names it ("rauto", "r4s",
            "25pct_k2"); a: the scale of its surface; description: what the
            layer is, as the program's file headers say; surface: a dict of
            what the surface extraction did (faces, vertices, parts,
            closed_parts, points_off_surface, fraction_of_points_on_surface;
            with normals, normal_agreement: the share of the surface's
            vertices whose normal points to the side their sheet faces, and
            sheets_with_inconsistent_normals: those oriented as without
            normals, their normals pointing to both sides alike).
    """

    _arrays = ("normal", "H", "K", "k1", "k2", "d1", "d2", "radius", "source", "distance", "H_sigma", "K_sigma",
               "normal_sigma", "H_noise_sigma")

    def __init__(self, values):
        for key in self._arrays:
            setattr(self, key, values.get(key))
        self.name = values.get("name")
        self.a = values.get("a")
        self.description = values.get("description")
        self.surface = values.get("surface")

    def __getitem__(self, key):
        if key not in self._arrays or getattr(self, key) is None:
            raise KeyError(key)
        return getattr(self, key)

    @property
    def shape_index(self):
        return shape_index(self.k1, self.k2)

    @property
    def curvedness(self):
        return curvedness(self.k1, self.k2)

    def keys(self):
        """The names of the layer's arrays."""
        return [key for key in self._arrays if getattr(self, key) is not None]

    def __len__(self):
        return len(self.H)

    def __repr__(self):
        label = f" {self.name!r}" if self.name is not None else ""
        label += f", a = {self.a:g}" if self.a is not None else ""
        return f"<Layer{label}: {len(self.H)} values>"

    def __eq__(self, other):
        """The same name, scale, description and surface report, and arrays equal to the bit."""
        if not isinstance(other, Layer):
            return NotImplemented
        return (self.name == other.name and _same_number(self.a, other.a) and self.description == other.description
                and _same_report(self.surface, other.surface)
                and all(_arrays_equal(getattr(self, key), getattr(other, key)) for key in self._arrays))

    __hash__ = None

    def colors(self, key="H", limit=None):
        """An (N, 3) float64 array of RGB colors in [0, 1] by the values of ``key``, as the program
        colors its surfaces: red where positive (convex for H), white at 0, blue where negative, grey
        where undefined (NaN); saturated at ``limit``, by default the 95th percentile of the magnitudes.
        For ``open3d.utility.Vector3dVector`` or a plot."""
        values = self[key]
        if values.ndim != 1:
            raise ValueError(f"colors: {key} is not a value per point; give H, K, k1, k2, radius or distance")
        finite = np.isfinite(values)
        if limit is None:
            magnitudes = np.sort(np.abs(values[finite]))
            limit = magnitudes[len(magnitudes) * 95 // 100] if len(magnitudes) else 1.0
        colors = np.full((len(values), 3), 128 / 255)
        if not limit > 0:
            return colors
        t = np.clip(values[finite] / limit, -1.0, 1.0)
        fade = np.round(255 * (1 - np.abs(t))) / 255
        colors[finite] = np.where((t >= 0)[:, None], np.column_stack([np.ones_like(t), fade, fade]),
                                  np.column_stack([fade, fade, np.ones_like(t)]))
        return colors


# A layer is noise-dominated when the median over its points of the noise's
# part of sigma_H / |H| exceeds this, bias-dominated when that of the whole
# sigma_H / |H| does and the noise's part does not (as the program's summary says).
DOMINATED_RELATIVE_UNCERTAINTY = 0.25


def _median_relative(sigma, H):
    """The median over the points with a value of ``sigma / |H|``; NaN without any (or without ``sigma``)."""
    if sigma is None:
        return float("nan")
    with np.errstate(divide="ignore", invalid="ignore"):
        relative = sigma / np.abs(H)
    relative = relative[~np.isnan(relative)]
    if not len(relative):
        return float("nan")
    return float(np.partition(relative, len(relative) // 2)[len(relative) // 2])


class Result:
    """What ``multiscale_curvatures`` returns.

    Attributes:
        layers: the layer names, in the program's order (scale by scale,
            neighborhoods inside); ``r[name]`` is the ``Layer``.
        points: (N, 3) float64, the input points (read-only).
        outlier: (N,) bool, the isolated far outliers, left off every surface
            (their values are NaN with source 2).
        spacing: the sample spacing, in units of the points ("4s" is four of them).
        noise: the estimated noise, in spacings (a ``NoiseEstimate``: a
            float with ``spacing``, ``noise_24`` and ``calls_for_denoising``).
        denoised: whether the points were smoothed before the shape was built.
        merged: how many points were equal to an earlier point: merged into
            it before any estimate, each copy has its point's values.
        (spacing, noise, denoised and merged are None in a Result read from a
        file that does not hold them: ``read_curvatures``.)

    Two results are equal (``==``) when their points, outliers, decisions
    and layers are the same to the bit.
    """

    def __init__(self, points, native):
        self._points = points
        self._layers = {values["name"]: Layer(values) for values in native["layers"]}
        self.layers = tuple(self._layers)
        self.outlier = native["outlier"]
        self.spacing = native["spacing"]
        self.noise = native["noise"] if "noise_24" not in native else NoiseEstimate(native)
        self.denoised = native["denoised"]
        self.merged = native.get("merged")
        for layer in self._layers.values():
            inconsistent = (layer.surface or {}).get("sheets_with_inconsistent_normals", 0)
            if inconsistent:
                warnings.warn(f"layer {layer.name}: the normals of {inconsistent} sheet(s) point about as often to "
                              "one side as to the other (unoriented normals?); those sheets are oriented as without "
                              "normals", stacklevel=3)
                break

    def uncertainty_summary(self):
        """Per layer name, as the program's summary gives it: ``(relative, relative_noise, dominated)``,
        the median over the points of sigma_H / |H|, the same of the noise's part of sigma_H, and
        ``"noise"`` when the latter exceeds ``DOMINATED_RELATIVE_UNCERTAINTY`` (the layer's values are
        mostly noise), ``"bias"`` when only the former does (H changes over the neighborhood: the
        value summarizes it rather than the point; ``"noise or bias"`` for a layer read from a file
        without H_noise_sigma), else None."""
        out = {}
        for name in self.layers:
            layer = self._layers[name]
            relative = _median_relative(layer.H_sigma, layer.H)
            relative_noise = _median_relative(layer.H_noise_sigma, layer.H)
            dominated = None
            if relative_noise > DOMINATED_RELATIVE_UNCERTAINTY:
                dominated = "noise"
            elif relative > DOMINATED_RELATIVE_UNCERTAINTY:
                dominated = "bias" if layer.H_noise_sigma is not None else "noise or bias"
            out[name] = (relative, relative_noise, dominated)
        return out

    def __getitem__(self, name):
        try:
            return self._layers[name]
        except KeyError:
            raise KeyError(f"no layer {name!r}; the layers are {', '.join(self.layers)}") from None

    def __iter__(self):
        return iter(self.layers)

    def __len__(self):
        return len(self.layers)

    @property
    def points(self):
        points = self._points.view()
        points.flags.writeable = False
        return points

    def __repr__(self):
        decisions = "" if self.spacing is None else f", spacing {self.spacing:g}, noise {self.noise:.3g}"
        return f"<Result: {len(self.outlier)} points, layers {', '.join(self.layers)}{decisions}>"

    def __eq__(self, other):
        if not isinstance(other, Result):
            return NotImplemented
        return (self.layers == other.layers and _arrays_equal(self._points, other._points)
                and _arrays_equal(self.outlier, other.outlier) and _same_number(self.spacing, other.spacing)
                and _same_number(self.noise, other.noise) and self.denoised == other.denoised
                and self.merged == other.merged
                and all(self[name] == other[name] for name in self.layers))

    __hash__ = None

    def to_structured(self, name):
        """One layer as a numpy structured array, a record per point (PDAL's arrays).

        Fields: X, Y, Z (the input points), NormalX, NormalY, NormalZ (PDAL's
        names), then H, K, k1, k2, d1x, d1y, d1z, d2x, d2y, d2z, radius,
        distance (float64), source (uint8) and outlier (bool).
        """
        layer = self[name]
        fields = [("X", "f8"), ("Y", "f8"), ("Z", "f8"), ("NormalX", "f8"), ("NormalY", "f8"),
                  ("NormalZ", "f8"), ("H", "f8"), ("K", "f8"), ("k1", "f8"), ("k2", "f8"),
                  ("d1x", "f8"), ("d1y", "f8"), ("d1z", "f8"), ("d2x", "f8"), ("d2y", "f8"),
                  ("d2z", "f8"), ("radius", "f8"), ("distance", "f8"), ("source", "u1"),
                  ("outlier", "?")]
        out = np.empty(len(self.outlier), dtype=fields)
        for i, axis in enumerate("XYZ"):
            out[axis] = self._points[:, i]
            out["Normal" + axis] = layer.normal[:, i]
        for key in ("H", "K", "k1", "k2", "radius", "distance", "source"):
            out[key] = getattr(layer, key)
        for direction in ("d1", "d2"):
            for i, axis in enumerate("xyz"):
                out[direction + axis] = getattr(layer, direction)[:, i]
        out["outlier"] = self.outlier
        return out

    def write_las(self, path, cloud=None):
        """Writes the values per point as LAS 1.4 to ``path`` (the program's ``--las``).

        Point format 6, or 7 when ``cloud`` has colors (8 with NIR); the
        curvature values as extra bytes described by the Extra Bytes VLR
        (record 4 of LASF_Spec) under the PLY's names (``outlier``, ``nx_L``
        .. ``distance_L`` as float32, ``source_L``), which lidR, PDAL and
        CloudCompare read as named attributes. ``cloud``: the ``PointCloud``
        that ``read_point_cloud`` gave for a LAS file, whose points these
        are: its scaled integers, scale, offset and fields (classification,
        returns, intensity, flags, GPS time, colors) are written as read,
        and so are its own extra bytes (their descriptors first in the Extra
        Bytes VLR, a field named as a curvature field replaced by it) and its
        CRS records (GeoTIFF keys, WKT, and the WKT bit).
        Without it the points are written with a power-of-ten scale that
        holds their range (at most half a step from each coordinate). The
        file is written beside ``path`` and renamed into place.
        """
        if cloud is not None and getattr(cloud, "fields", None) is None:
            raise ValueError("write_las: cloud must be the PointCloud of a LAS file (read_point_cloud)")
        if cloud is not None and len(cloud.fields["X"]) != len(self._points):
            raise ValueError(f"write_las: the cloud has {len(cloud.fields['X'])} points, the result "
                             f"{len(self._points)}")
        if cloud is not None:
            info = dict(cloud.las)
            fields = cloud.fields
        else:
            if len(self._points):
                scale, offset = _native.las_scale(list(self._points.min(axis=0)), list(self._points.max(axis=0)))
            else:
                scale, offset = (0.001,) * 3, (0.0,) * 3
            info = {"scale": scale, "offset": offset, "rgb": False}
            fields = None
        layers = [vars(self[name]) for name in self.layers]
        records, stats = _native.las_records(self._points, self.outlier, layers, fields, info)
        header, evlrs = _native.las_header(info, list(self.layers), len(self._points), list(stats["min"]),
                                           list(stats["max"]), list(stats["by_return"]))
        def write(temporary):
            with open(temporary, "wb") as f:
                f.write(header)
                f.write(records)
                f.write(evlrs)
        atomic_write(path, write)

    def to_dataframe(self, name):
        """One layer as a pandas DataFrame, a row per point, the columns of ``to_structured(name)``.

        Needs pandas (Debian's python3-pandas), which the module does not depend on otherwise.
        """
        try:
            import pandas
        except ImportError:
            raise ImportError("to_dataframe needs pandas (apt-get install python3-pandas); "
                              "to_structured() gives the same columns as a numpy structured array") from None
        return pandas.DataFrame(self.to_structured(name))

    def write_ply(self, path, precision="float64"):
        """Writes the values to ``path`` as the program's ``curvatures.ply``; returns ``path``.

        A binary little-endian PLY point cloud: per point x y z (float64),
        outlier, and per layer L the properties nx_L ny_L nz_L H_L K_L k1_L
        k2_L d1x_L .. d2z_L radius_L distance_L and the uchar source_L, the
        scalar fields CloudCompare shows by name, and a comment line per layer.

        precision: "float64" (default), the values as doubles with the run's
            decisions (spacing, noise, smoothing, each layer's scale and surface
            report) in one more comment line, so that ``read_curvatures`` gives
            back a Result equal to this one to the bit; or "float32", the
            program's file, the same bytes as ``conformal_curvature`` on the
            same points and options (half the size).

        The file is written beside ``path`` and renamed into place, so it is
        never half written; it gets a new file's mode (-rw-r--r-- under umask
        022). Errors (a missing folder, no permission) name ``path``.
        """
        path = os.fspath(path)
        if precision == "float64":
            curvature_file.write_double_ply(path, self._points, self.outlier, [self[name] for name in self.layers],
                                            self.spacing, self.noise, self.denoised, self.merged)
        elif precision == "float32":
            atomic_write(path, lambda temporary: _native.write_point_cloud(
                temporary, self._points, self.outlier, [vars(self[name]) for name in self.layers]))
        else:
            raise ValueError(f"write_ply: precision must be 'float32' or 'float64', got {precision!r}")
        return path


def read_curvatures(path):
    """The ``Result`` a ``curvatures.ply`` holds: the program's file, ``Result.write_ply``'s, or the
    merged file (and the parts) of a tiled run.

    From a file of ``write_ply(path)`` the Result is equal (``==``) to the one
    that wrote it, to the bit. From the program's float32
    file the values are its floats, the layers' scales ``a`` as their header
    comments print them (6 digits), and ``spacing``, ``noise``, ``denoised``,
    ``merged`` and the layers' ``surface`` reports are None (the file does not
    hold them);
    writing that Result again with ``precision="float32"`` gives the same bytes.

    Raises:
        OSError: a missing or unreadable file.
        ValueError: a file that is not such a point cloud (the message names it).
    """
    points, values = curvature_file.read_values(path)
    return Result(points, values)


def _job_arguments(points, normals, radii, rings, estimator, denoise, denoise_neighbors, extraction, threads,
                   progress, spacing, noise, function="multiscale_curvatures", needs_spacing=True):
    """The checked arguments of the native job but its scales: (points, normals, the rest as it takes them).

    ``function`` names the caller in messages; ``needs_spacing``: whether the
    job's curvature will be estimated (its radii in spacings need the spacing).
    """
    if (spacing is None) != (noise is None):
        raise ValueError("spacing and noise are given together (the decisions of a larger run) or not at all")
    for name, value in (("spacing", spacing), ("noise", noise)):
        if value is not None and (isinstance(value, bool) or not isinstance(value, numbers.Real)):
            raise TypeError(f"{name} must be a float or None, got {value!r}")
    points = _triples(points, "points")
    if normals is not None:
        normals = _triples(normals, "normals")
        if len(normals) != len(points):
            raise ValueError(f"normals must be an (N, 3) array with N = {len(points)} (one per point), "
                             f"got shape {normals.shape}")
    if denoise is True or denoise is False:
        denoise = "on" if denoise else "off"
    if denoise_neighbors is not None and (isinstance(denoise_neighbors, bool)
                                          or not isinstance(denoise_neighbors, numbers.Integral)):
        raise TypeError(f"denoise_neighbors must be an int or None, got {denoise_neighbors!r}")
    if progress is not None and not callable(progress):
        raise TypeError(f"progress must be callable as progress(stage, fraction), got {progress!r}")
    _check_shape_points(function, points)
    radii = _option_items(radii, "radii")
    in_spacings = [item for item in radii if item == "auto" or item.endswith("s")]
    if needs_spacing and spacing is None and in_spacings and len(points) < _NOISE_POINTS:
        raise ValueError(f"{function}: {_points_text(len(points))}; radii in sample spacings ({', '.join(in_spacings)}) "
                         f"need the sample spacing, estimated from each point's {_NOISE_POINTS - 1} nearest "
                         f"neighbors: at least {_NOISE_POINTS} points; give the radii as lengths (radii=[0.1]) or "
                         "rings (rings=[1], radii=[]), or spacing= and noise=")
    return (points, normals, radii, _option_items(rings, "rings", integers=True),
            _choice(estimator, "estimator"), _choice(denoise, "denoise"),
            "" if denoise_neighbors is None else str(int(denoise_neighbors)),
            _choice(extraction, "extraction"), _threads(threads), progress,
            None if spacing is None else float(spacing), None if noise is None else float(noise),
            float(noise.noise_24) if isinstance(noise, NoiseEstimate) else None)


def _job(points, normals=None, *, radii=("auto",), rings=(), estimator="quadric", denoise="auto",
         denoise_neighbors=None, extraction="front", threads=None, progress=None, spacing=None, noise=None,
         scales=1, function="multiscale_curvatures"):
    """The native job of these points and options, its shape built: ``closing_values()``,
    ``result(scales, progress)`` (the dict ``Result`` takes; the job's last call, which frees
    the shape) and ``release()``. ``scales``: how many scales ``result`` will be given
    (0: only the closing values will be asked for), for the shares of the progress."""
    arguments = _job_arguments(points, normals, radii, rings, estimator, denoise, denoise_neighbors, extraction,
                               threads, progress, spacing, noise, function=function, needs_spacing=scales > 0)
    return _native.Job(*arguments, scales=scales)


def multiscale_curvatures(points, normals=None, *, scales=("auto",), radii=("auto", "2s", "4s", "8s", "16s"),
                          rings=(), estimator="quadric", denoise="auto", denoise_neighbors=None,
                          extraction="front", threads=None, progress=None, spacing=None, noise=None):
    """Curvature of every point of a cloud at several scales: the program's job.

    The points are checked, recentered and rescaled, isolated far outliers
    left out; the noise is estimated and, when it calls for it, the points
    are smoothed; the conformal alpha shape is built once; then for each
    scale its surface is extracted and oriented, its curvature estimated
    for each neighborhood and given to every input point. The same values
    to the last bit as ``conformal_curvature`` on the same points and options.

    Parameters:
        points: (N, 3) array of the points (float64; other real dtypes and
            layouts are converted).
        normals: optional (N, 3) array, a normal per point (a scanner's):
            each sheet of the surface is oriented by the majority of its
            points' normals where they are consistent, and each of its
            points' values by the point's own normal; where they point
            about as often to one side as to the other (unoriented normals,
            random signs) the sheet is oriented as without normals, its
            points' values follow it, and a warning says so.
        scales: the conformal scales ``a``: "auto" (the smallest at which the
            surface covers the sample), a value > 0, or a quantile of the
            facet values as "25%" (the paper's figures use 10%, 25%, 35%, 50%).
        radii: neighborhood radii of the curvature fit: "auto" (chosen per
            point), a multiple of the sample spacing as "4s", or a length in
            units of the points (a number, or "0.01").
        rings: ring sizes from 1 to 100, besides or instead of radii.
        estimator: "quadric" (default), "euler-least-squares" or "paper".
        denoise: "auto" (smooth when the estimated noise exceeds 0.02
            spacings), "on"/True or "off"/False.
        denoise_neighbors: neighbors of the smoothing jet fit (>= 7); default
            from the estimated noise.
        extraction: "front" (one sheet per part, open or closed) or "solid"
            (the boundary of the enclosed solid).
        threads: the most threads to use (TBB); None for all. The results
            are the same with any number.
        progress: optional callable ``progress(stage, fraction)``: the step's
            name and the fraction done in [0, 1], in proportion to the time
            the steps take; called at each step's start and every 0.1 s or so
            inside, never decreasing, last with ("done", 1.0).
        spacing, noise: the decisions of a larger run, both or neither: the
            sample spacing (in units of the points) and the noise (in
            spacings) of the whole cloud these points are part of, as
            ``r.spacing`` and ``r.noise`` of a run on it (e.g. when each tile
            of a cloud is run alone). They are used instead of an estimate
            on these points: for radii in spacings ("4s"), the "auto" radius,
            the noise level of the fits and the "auto" denoising decision.
            Given a run's own ``r.spacing`` and ``r.noise``, a run on the same
            points gives the same values to the last bit. The "auto"
            denoising decision also reads the noise with 24 neighbors, which
            ``r.noise`` and ``estimate_noise()`` carry (a ``NoiseEstimate``);
            given a plain float, it reads that noise alone (smoothing above
            0.02 spacings), so pass ``denoise`` too.

    Returns:
        A ``Result``: ``r.layers`` the layer names, ``r[name]`` a ``Layer``.

    Raises:
        ValueError: NaN or infinite coordinates (naming the index), points
            that do not span 3D (fewer than 4 distinct, coplanar), radii in
            spacings ("auto", "4s") on fewer than 25 points or on points whose
            spacing cannot be estimated (without spacing= and noise=), a scale
            or radius out of range, an unknown option, wrong shapes, only one of
            spacing and noise, a spacing not finite and > 0, a noise < 0 or NaN.
        TypeError: arrays that are not of real numbers, options of the wrong type.
        KeyboardInterrupt: Ctrl-C (within about a second, the work unwound).
    """
    arguments = _job_arguments(points, normals, radii, rings, estimator, denoise, denoise_neighbors, extraction,
                               threads, progress, spacing, noise)
    points = arguments[0]
    native = _native.multiscale_curvatures(points, arguments[1], _option_items(scales, "scales"), *arguments[2:])
    return Result(points, native)


def front_closing_values(points, normals=None, *, denoise="auto", denoise_neighbors=None, threads=None,
                         progress=None, spacing=None, noise=None):
    """Per point, the local closing value of the advancing front: a tile's share of the automatic scale.

    The steps of ``multiscale_curvatures`` up to the front (the same checks,
    outliers, noise decisions, smoothing and shape, with the same keywords),
    then for each point the upper quartile (the 19th smallest of 24) of the
    closing values of its vertex and the 23 nearest vertices of the front,
    those not NaN (a vertex's closing value: the smallest scale at which the
    complex holds a fan of facets around it, a value of its star that a
    tile's halo does not change). The
    automatic scale "auto" (with extraction "front") is the mean of the
    sorted values that are not NaN of ranks 0.99 n to 0.999 n (a trimmed
    tail: no single value decides it), so the scale of a cloud split
    into tiles is that mean over the tiles' values pooled (each point
    counted in one tile only).

    Returns:
        (N,) float64: NaN for outliers, for points the front does not reach,
        for points on the convex hull with no fan of finite facets around
        them and for all but the first of coincident points (they share a
        vertex).
    """
    job = _job(points, normals, denoise=denoise, denoise_neighbors=denoise_neighbors, threads=threads,
               progress=progress, spacing=spacing, noise=noise, scales=0, function="front_closing_values")
    closing = job.closing_values()
    job.release()
    return closing


class ConformalAlphaShape:
    """The conformal alpha shape (filtration) of a point cloud, in its coordinates.

    Each point's ball grows with its local feature size (by default its
    distance to its Voronoi pole, at least 4 sample spacings); a simplex
    enters the filtration at its conformal value, its empty ball's radius
    relative to the local feature sizes of its points. Unlike ``multiscale_curvatures``, the
    points are used as given (not recentered, no outlier removal, no smoothing).

    Parameters:
        points: (N, 3) array.
        local_scales: optional (N,) array of positive local feature sizes,
            one per point (C++: ``local_feature_sizes``), instead of the pole
            distances (all 1: the classic alpha
            shape, ``a`` a squared radius as in CGAL's Alpha_shape_3).

    Attributes and protocols: ``points`` (the (N, 3) points, read-only),
    ``len(shape)`` (N), ``dimension`` (3), ``local_feature_sizes`` (per
    point), ``repr``; a shape pickles as its points (and the local scales
    given) and is rebuilt when unpickled, with the same spectrum: it can be
    sent to Dask's workers.

    Raises:
        ValueError: fewer than 4 points, points that do not span 3D, NaN or
            infinite coordinates (naming the index), local feature sizes that
            are not finite and positive (naming the index).
    """

    def __init__(self, points, local_scales=None):
        points = np.array(_triples(points, "points"), dtype=np.float64, order="C")  # a copy of its own
        points.flags.writeable = False
        _check_shape_points("ConformalAlphaShape", points)
        if local_scales is not None:
            local_scales = _real_array(local_scales, "local_scales")
            if local_scales.shape != (len(points),):
                raise ValueError(f"local_scales must be an (N,) array with N = {len(points)}, "
                                 f"got shape {local_scales.shape}")
            local_scales = np.array(local_scales, dtype=np.float64, order="C")
            local_scales.flags.writeable = False
        self._points = points
        self._local_scales = local_scales
        self._shape = _native.Shape(points, local_scales)

    def __reduce__(self):
        return (ConformalAlphaShape, (self._points, self._local_scales))

    def __len__(self):
        return len(self._points)

    def __repr__(self):
        return (f"<ConformalAlphaShape: {len(self._points)} points, dimension {self.dimension}, "
                f"{len(self.spectrum())} values in the spectrum>")

    @property
    def points(self):
        """The (N, 3) float64 points, as given (read-only)."""
        return self._points

    @property
    def dimension(self):
        """The dimension of the triangulation (3 for points that span 3D)."""
        return self._shape.dimension()

    @property
    def local_feature_sizes(self):
        """The (N,) local feature size of each point (of its vertex, for coincident points)."""
        return self._shape.local_feature_sizes()

    def spectrum(self):
        """The sorted distinct conformal values of the simplices (float64 array)."""
        return self._shape.spectrum()

    def alpha_at_quantile(self, q):
        """The quantile ``q`` in [0, 1] of the finite facets' values (the paper's scale choice)."""
        if isinstance(q, bool) or not isinstance(q, numbers.Real):
            raise TypeError(f"alpha_at_quantile: q must be a number in [0, 1], got {q!r}")
        if not 0 <= q <= 1:
            raise ValueError(f"alpha_at_quantile: the quantile q must be in [0, 1], got {q}")
        return self._shape.alpha_at_quantile(float(q))

    def suggest_scale(self, extraction="front", coverage=None):
        """The automatic scale: the smallest ``a`` whose surface covers the sample.

        ``coverage`` is the share to cover (default 0.99 of the front's
        vertices with "front", 0.9 of the points with "solid").
        """
        if coverage is not None:
            if isinstance(coverage, bool) or not isinstance(coverage, numbers.Real):
                raise TypeError(f"suggest_scale: coverage must be a number in (0, 1], got {coverage!r}")
            if not 0 < coverage <= 1:
                raise ValueError(f"suggest_scale: coverage must be in (0, 1], got {coverage}")
        return self._shape.suggest_scale(_choice(extraction, "extraction"),
                                         None if coverage is None else float(coverage))

    def classify_facets(self, a):
        """Counts of the finite facets per class at scale ``a``: a dict with
        keys "exterior", "singular", "regular", "interior" (Alpha_shape_3's classes)."""
        return self._shape.classify_facets(_check_scale("classify_facets", a))

    def surface(self, a=None, extraction="front"):
        """The oriented surface at scale ``a`` (default: ``suggest_scale()``).

        Returns ``(vertices, faces, point_index)``: (V, 3) float64 positions,
        (F, 3) int64 vertex indices of the triangles (counterclockwise seen
        from the side the normals point to), (V,) int64 the index of each
        vertex's input point. Below every facet's value the surface is empty.

        Raises ValueError for a NaN or negative ``a``.
        """
        return self._shape.surface(None if a is None else _check_scale("surface", a),
                                   _choice(extraction, "extraction"))


def vertex_curvatures(vertices, faces, *, rings=None, radius=None, estimator="quadric"):
    """Curvature at every vertex of a triangle mesh.

    Parameters:
        vertices: (V, 3) array of positions.
        faces: (F, 3) integer array of vertex indices, consistently oriented
            (an oriented 2-manifold, with or without border).
        rings: the neighborhood in rings of vertices (default 1), or
        radius: a neighborhood radius in units of the vertices.
        estimator: "quadric" (default), "euler-least-squares" or "paper".

    Returns:
        A ``Layer`` with normal, H, K, k1, k2, d1, d2 and radius per vertex
        (NaN where the curvature is undefined, e.g. an isolated vertex).
    """
    vertices = _triples(vertices, "vertices", "V")
    faces = _real_array(faces, "faces")
    if faces.dtype.kind == "f":
        raise TypeError(f"faces must be an array of integers, got dtype {faces.dtype}")
    if faces.ndim != 2 or faces.shape[1] != 3:
        raise ValueError(f"faces must be an (F, 3) array, got shape {faces.shape}")
    if rings is not None and (isinstance(rings, bool) or not isinstance(rings, numbers.Integral)):
        raise TypeError(f"rings must be an int, got {rings!r}")
    return Layer(_native.vertex_curvatures(vertices, np.ascontiguousarray(faces, dtype=np.int64),
                                           None if rings is None else int(rings),
                                           None if radius is None else float(radius),
                                           _choice(estimator, "estimator")))


class NoiseEstimate(float):
    """The noise of a sample in sample spacings (a float), with

    spacing: the sample spacing, in units of the points;
    noise_24: the same reading with 24 neighbors instead of 16 (it grows
        where the sampling does not resolve surface detail);
    calls_for_denoising: whether ``multiscale_curvatures`` smooths the points.
    """

    def __new__(cls, values):
        self = super().__new__(cls, values["noise"])
        self.spacing = values["spacing"]
        self.noise_24 = values["noise_24"]
        self.calls_for_denoising = values["calls_for_denoising"]
        return self

    def __repr__(self):
        return f"NoiseEstimate({float(self):.4g} spacings, spacing {self.spacing:.4g})"

    def __reduce__(self):
        return (NoiseEstimate, ({"noise": float(self), "spacing": self.spacing, "noise_24": self.noise_24,
                                 "calls_for_denoising": self.calls_for_denoising},))


def _unchecked_noise_estimate(points):
    """The library's estimate as it is: all zero for fewer than 25 points or no fit (tiled runs
    pool it over tiles, some of which may be that small)."""
    return NoiseEstimate(_native.estimate_noise(_triples(points, "points")))


def estimate_noise(points):
    """The noise of a point sample of a surface, in sample spacings (a ``NoiseEstimate``).

    Raises:
        ValueError: fewer than 25 points (a cubic is fitted to each sampled
            point's 24 nearest neighbors), or points on which no fit can be
            made (all coincident or on a line): the spacing cannot be estimated.
    """
    points = _triples(points, "points")
    _check_noise_points("estimate_noise", points)
    estimate = _unchecked_noise_estimate(points)
    if not estimate.spacing > 0:
        raise ValueError(f"estimate_noise: the noise and the sample spacing cannot be estimated on these "
                         f"{len(points)} points: no sampled point has {_NOISE_POINTS - 1} nearest neighbors that are "
                         "not coincident or on a line")
    return estimate


def denoise(points, neighbors=None):
    """The points smoothed as ``multiscale_curvatures`` smooths them: a new (N, 3) array.

    Each point is projected onto a quadratic jet fitted to its ``neighbors``
    nearest points (>= 7; default, and the number of passes, from the
    estimated noise).
    """
    if neighbors is not None and (isinstance(neighbors, bool) or not isinstance(neighbors, numbers.Integral)):
        raise TypeError(f"neighbors must be an int or None, got {neighbors!r}")
    points = _triples(points, "points")
    _check_noise_points("denoise", points)
    return _native.denoise(points, None if neighbors is None else int(neighbors))


class PointCloud(tuple):
    """What ``read_point_cloud`` returns: the pair ``(points, normals)``, with

    points: (N, 3) float64; normals: (N, 3) float64 or None;
    fields: for a LAS file, a dict of (N,) arrays, the fields of the points
        kept: classification, return_number, number_of_returns, intensity,
        withheld, synthetic, key_point, overlap (bool), gps_time,
        point_source_id, user_data, scan_angle (int16, in 0.006 degrees),
        scanner_channel, scan_direction, edge_of_flight_line, red, green,
        blue, nir, the scaled integers X, Y, Z, and extra_bytes, an (N, m)
        uint8 array of each record's bytes beyond its point format's (m is
        ``las["extra_bytes_length"]``); else None;
    las: for a LAS file, its header (version, point_format, number_of_points,
        scale, offset, rgb, nir, global_encoding, ...), its extra-bytes
        fields (``las["extra_bytes"]``: name, data_type, offset and size in
        ``fields["extra_bytes"]``, and the 192-byte descriptor of the Extra
        Bytes VLR; bytes that no descriptor names are a field
        "undescribed_extra_bytes" of data type 0) and its CRS records
        (``las["crs"]``: user_id, record_id, description and data of the
        GeoTIFF keys 34735, 34736, 34737 and the WKT 2112, VLRs then
        EVLRs); else None;
    counts: for a LAS file, how many points were read and how many each
        filter kept, in order (read, classes, withheld, returns); else None;
    summary: for a LAS file, the program's summary line of the input.
    """

    def __new__(cls, native):
        self = super().__new__(cls, (native["points"], native["normals"]))
        self.points = native["points"]
        self.normals = native["normals"]
        self.fields = native.get("fields")
        self.las = native.get("las")
        self.counts = native.get("counts")
        self.summary = native.get("summary")
        return self

    def __repr__(self):
        kind = f" LAS {self.las['version']} format {self.las['point_format']}" if self.las else ""
        return f"<PointCloud{kind}: {len(self.points)} points>"


def read_point_cloud(path, *, classes=None, drop_withheld=False, returns="all"):
    """The points of a .xyz, .pwn, .ply, .off, .obj or .las file, as the program reads them.

    Returns a ``PointCloud``: unpacks as ``points, normals = read_point_cloud(path)``
    (normals None when the file has none), and for a LAS file (1.0 to 1.4,
    point formats 0 to 10, uncompressed) holds the points' fields as arrays
    (``cloud.fields["classification"]``, ...), the header and the filters'
    counts. The filters, for LAS only (the program's ``--classes``,
    ``--drop-withheld`` and ``--returns``):

        classes: the classes to keep (e.g. ``[2, 6]``), None for all;
        drop_withheld: leave out the points flagged withheld;
        returns: "all", "first" (return number 1, or 0: unset) or "last"
            (return number = number of returns).

    Raises:
        ValueError: a bad file, naming it and what is wrong (a .laz file or a
            compressed LAS is refused, with how to decompress it), a filter on
            other input, a bad filter.
    """
    if classes is None:
        classes = ()
    elif isinstance(classes, numbers.Integral):
        classes = (classes,)
    classes = _option_items(classes, "classes", integers=True)
    if not isinstance(drop_withheld, bool):
        raise TypeError(f"drop_withheld must be a bool, got {drop_withheld!r}")
    return PointCloud(_native.read_point_cloud(os.fspath(path), classes, drop_withheld,
                                               _choice(returns, "returns")))
