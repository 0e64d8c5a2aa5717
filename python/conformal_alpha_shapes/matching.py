"""Shape descriptors of surface regions, and matching them from one surface to another.

The sampling, the descriptors, their distances and the registration are the
C++ library's (region_descriptors.h, match_regions.h), run with the GIL
released on the threads that ``threads`` allows; numpy in and out. Lengths
are in the units of the points; curvatures in inverse units.

- ``shape_index(k1, k2)`` and ``curvedness(k1, k2)``: Koenderink's per-point
  shape descriptors from the principal curvatures.
- ``farthest_point_sample(points, n)``: n well-spread point indices.
- ``region_descriptors(points, layers, centers, normals=...)``: for each
  centre point, the histograms of shape index and curvedness of the points
  around it, at each curvature scale (layer), and of the normals' angles
  and heights, in each of a few concentric rings.
- ``histogram_distances(a, b)``: the earth mover's distance of every
  histogram, the rings weighted by their radius.
- ``match_regions(a, b)``: for each region of A, the best candidates of B by
  those distances, a rigid registration from those matches (RANSAC over
  triples, then a least-squares fit on the consistent ones) that places B
  onto A, and the candidates re-ranked by their agreement with it.
"""

import math

import numpy as np

from . import _native

__all__ = [
    "Matches",
    "Regions",
    "chi_square_distances",
    "curvedness",
    "farthest_point_sample",
    "fit_rigid",
    "histogram_distances",
    "match_regions",
    "region_descriptors",
    "register_correspondences",
    "shape_index",
]


def shape_index(k1, k2):
    """Koenderink's shape index S = (2/pi) atan((k1 + k2) / (k1 - k2)), k1 >= k2, in [-1, 1].

    The curvatures follow the outward normal (a sphere with outward normals
    has k1 = k2 = 1/r > 0), so S = +1 on a convex cap (a bump), -1 on a
    concave cup (a pit), +0.5 on a ridge (a convex cylinder), -0.5 on a rut,
    0 on a symmetric saddle. Umbilic points (k1 = k2 != 0) get +1 or -1 by
    their sign; flat points (k1 = k2 = 0) have no shape index: NaN. The
    order of k1 and k2 does not matter (they are sorted); NaN in, NaN out.
    """
    k1 = np.asarray(k1, dtype=np.float64)
    k2 = np.asarray(k2, dtype=np.float64)
    hi, lo = np.maximum(k1, k2), np.minimum(k1, k2)
    with np.errstate(invalid="ignore"):
        s = (2 / math.pi) * np.arctan2(hi + lo, hi - lo)
    s = np.where((hi == 0) & (lo == 0), np.nan, s)
    return s if s.ndim else float(s)


def curvedness(k1, k2):
    """Koenderink's curvedness C = sqrt((k1^2 + k2^2) / 2) >= 0, in inverse units of the points
    (1/r on a sphere or a plane's 0); how much the surface bends, whatever its shape."""
    k1 = np.asarray(k1, dtype=np.float64)
    k2 = np.asarray(k2, dtype=np.float64)
    c = np.sqrt((k1 * k1 + k2 * k2) / 2)
    return c if c.ndim else float(c)


def _points(values, name):
    array = np.asarray(values, dtype=np.float64)
    if array.ndim != 2 or array.shape[1] != 3:
        raise ValueError(f"{name} must be an (N, 3) array, got shape {array.shape}")
    if not np.all(np.isfinite(array)):
        raise ValueError(f"{name}: NaN or infinite coordinates")
    return np.ascontiguousarray(array)


def farthest_point_sample(points, n, first=0):
    """Indices of n points of the cloud chosen greedily, each the farthest from those chosen before,
    starting from index ``first``: a spread-out sample, the same on every run. All the indices when
    n >= len(points)."""
    points = _points(points, "points")
    if int(n) != n or n < 0:
        raise ValueError("farthest_point_sample: n must be an integer >= 0")
    if not 0 <= first < max(len(points), 1):
        raise ValueError("farthest_point_sample: first must be a point index")
    return _native.farthest_point_sample(points, int(n), int(first))


def _layer_arrays(layers, count):
    """The (k1, k2, radius) of every point at every layer: three (L, N) arrays."""
    if hasattr(layers, "layers") and hasattr(layers, "__getitem__") and not isinstance(layers, (list, tuple)):
        layers = [layers[name] for name in layers.layers]
    if isinstance(layers, dict) or hasattr(layers, "k1"):
        layers = [layers]
    if not layers:
        raise ValueError("region_descriptors: no curvature layer")
    arrays = []
    for key in ("k1", "k2", "radius"):
        values = [np.asarray(layer[key], dtype=np.float64).ravel() for layer in layers]
        for v in values:
            if len(v) != count:
                raise ValueError(f"region_descriptors: {count} points but {len(v)} values per layer")
        arrays.append(np.ascontiguousarray(np.stack(values)))
    return arrays


class Regions:
    """Descriptors of regions of a surface.

    Attributes:
        points: (N, 3) the surface's points; centers: (M,) indices of the
            regions' centre points; descriptors: (M, D) float64, each row a
            concatenation of normalised histograms (sum 1 each, all zeros
            for an empty ring): per ring, per layer the shape index bins then
            the curvedness bins, then (with normals) the normal cosine bins
            and the height bins.
        rings: the rings' outer radii; bins: (shape index bins, curvedness bins);
            histograms: the number of histograms in a row; histogram_bins,
            histogram_weights and histogram_kinds: (histograms,) each
            histogram's bins, its weight in ``histogram_distances`` and its
            kind (what it counts, whatever the ring: 0 and 1 the first
            layer's shape index and curvedness, 2 and 3 the second's, ...,
            then the normals' cosines and the heights).
    """

    def __init__(self, points, centers, descriptors, rings, bins, histogram_bins, histogram_weights,
                 histogram_kinds):
        self.points = points
        self.centers = centers
        self.descriptors = descriptors
        self.rings = tuple(rings)
        self.bins = tuple(bins)
        self.histogram_bins = np.asarray(histogram_bins, dtype=np.int64)
        self.histogram_weights = np.asarray(histogram_weights, dtype=np.float64)
        self.histogram_kinds = np.asarray(histogram_kinds, dtype=np.int64)
        self.histograms = len(self.histogram_bins)  # how many normalised histograms each row holds

    def __len__(self):
        return len(self.centers)

    def __repr__(self):
        return (f"<Regions: {len(self.centers)} centres, {self.descriptors.shape[1]} values each, rings "
                f"{self.rings}>")


def _soft_bins(values, low, high, bins):
    """Linear (two nearest bin centres) histogram weights of values in [low, high]: (index, weight) pairs."""
    t = (np.clip(values, low, high) - low) / (high - low) * bins - 0.5
    t = np.clip(t, 0, bins - 1)
    i0 = np.floor(t).astype(np.int64)
    i1 = np.minimum(i0 + 1, bins - 1)
    w1 = t - i0
    return i0, 1 - w1, i1, w1


def _unit(vectors, name, count):
    vectors = _points(vectors, name)
    if len(vectors) != count:
        raise ValueError(f"region_descriptors: {count} points but {len(vectors)} {name}")
    return vectors / np.maximum(np.linalg.norm(vectors, axis=1, keepdims=True), 1e-300)


def region_descriptors(points, layers, centers=None, *, normals=None, center_normals=None,
                       rings=(3.0, 6.0, 10.0), shape_bins=10, curvedness_bins=6, curvedness_range=2.0,
                       geometry_bins=8, ring_weights="radius", dense_radius=4.0, thinning=3,
                       threads=None):
    """Descriptors of the surface around chosen centre points, at every curvature scale, in rings.

    For each centre, the points of the surface within each ring of distance
    (0 to rings[0], rings[0] to rings[1], ...; model units) are summarised,
    for each curvature layer, by a histogram of their shape index (over
    [-1, 1]) and one of their curvedness times the layer's fit radius (over
    [0, curvedness_range], the last bin taking larger values); each
    histogram is soft (a value shares its weight between the two nearest
    bins) and normalised to sum 1 (all zeros for an empty ring). Points
    without a shape index (flat, or NaN) count in neither histogram.
    Distances are Euclidean in space, so the rings suit surfaces whose
    sheets are farther apart than the largest ring's width.

    Parameters:
        points: (N, 3) the surface's points.
        layers: the curvature of the points: a ``Result`` (all its layers),
            a ``Layer``, or a list of them (any objects with per-point
            ``k1``, ``k2`` and ``radius``, e.g. dicts of arrays).
        centers: None (every point), an int n (a farthest-point sample of n
            points) or an array of point indices.
        normals: optional (N, 3) outward normals: then, per ring, also
            histograms (``geometry_bins`` bins) of the cosine between the
            centre's normal and the points' normals and of the points'
            heights over the centre's tangent plane over the ring's radius.
        center_normals: optional (N, 3) normals giving the centre's tangent
            plane (default ``normals``): a layer's fitted normal at a few
            angstroms (e.g. ``result["r3"].normal``) is steadier than the
            sampled surface's, which follows each atom.
        rings: increasing outer radii of the rings.
        shape_bins, curvedness_bins, geometry_bins: the histograms' bins.
        curvedness_range: the end of the last curvedness bin, for C x radius.
        ring_weights: the weight of each ring's histograms in
            ``histogram_distances``: "radius" (proportional to the ring's
            outer radius: the outer rings hold more points, so their
            histograms are less noisy, and their context tells apart
            patches alike at the centre), "equal", or one value per ring.
        dense_radius, thinning: beyond ``dense_radius`` from the centre, only
            one point in ``thinning`` (by index) counts: the rings there hold
            hundreds to thousands of points, whose normalised histograms a
            third of them gives nearly as well (hit rates within 0.02 on
            the benchmark's pairs) in half the time. ``thinning=1``: every
            point everywhere.
        threads: how many threads share the centres (default: the CPUs).

    Returns:
        ``Regions``.
    """
    points = _points(points, "points")
    k1, k2, radius = _layer_arrays(layers, len(points))
    rings = np.asarray(rings, dtype=np.float64)
    if rings.ndim != 1 or len(rings) == 0 or not np.all(rings > 0) or np.any(np.diff(rings) <= 0):
        raise ValueError("region_descriptors: rings must be increasing radii > 0")
    if int(thinning) != thinning or thinning < 1 or not dense_radius > 0:
        raise ValueError("region_descriptors: thinning must be an integer >= 1 and dense_radius > 0")
    if isinstance(ring_weights, str):
        if ring_weights not in ("radius", "equal"):
            raise ValueError("region_descriptors: ring_weights must be 'radius', 'equal' or one value per ring")
        ring_weights = rings / rings.mean() if ring_weights == "radius" else np.ones(len(rings))
    ring_weights = np.asarray(ring_weights, dtype=np.float64)
    if ring_weights.shape != rings.shape or np.any(ring_weights < 0):
        raise ValueError("region_descriptors: ring_weights must be 'radius', 'equal' or one value >= 0 per ring")
    if centers is None:
        centers = np.arange(len(points))
    elif np.isscalar(centers) and float(centers) == int(centers):
        centers = farthest_point_sample(points, int(centers))
    else:
        centers = np.asarray(centers, dtype=np.int64)
        if centers.ndim != 1 or (len(centers) and (centers.min() < 0 or centers.max() >= len(points))):
            raise ValueError("region_descriptors: centers must be point indices")
    centers = np.ascontiguousarray(centers, dtype=np.int64)
    if normals is not None:
        normals = _points(normals, "normals")
        center_normals = None if center_normals is None else _points(center_normals, "center_normals")
    descriptors, histogram_bins, histogram_weights, histogram_kinds = _native.region_descriptors(
        points, k1, k2, radius, centers, normals, center_normals, rings.tolist(), ring_weights.tolist(),
        int(shape_bins), int(curvedness_bins), float(curvedness_range), int(geometry_bins), float(dense_radius),
        int(thinning), _threads(threads))
    return Regions(points, centers, descriptors, rings, (shape_bins, curvedness_bins), histogram_bins,
                   histogram_weights, histogram_kinds)


def _threads(threads):
    """The native functions' thread count: 0 for all the CPUs."""
    if threads is None:
        return 0
    if int(threads) != threads or threads < 1:
        raise ValueError("threads must be an integer >= 1, or None for all the CPUs")
    return int(threads)


def histogram_distances(a, b, threads=None, balance=True):
    """(len(a), len(b)) distances between the regions of ``Regions`` a and b, from the earth mover's
    distance between each pair of histograms as a share of the histogram's range (the L1 distance
    of the running sums over the bins' count), weighted by ring.

    The bins are ordered (a shape index of 0.9 is near 1.0, far from -1.0); the chi-square
    distance compares bins one by one, so a shape shifted by one bin looks as far as one at the
    other end, and the earth mover's distance ranks the true places higher.

    balance: True (default): the weighted sum over each kind of histogram (one layer's shape
    index, one layer's curvedness, the normals' cosines, the heights: all rings) is divided by its
    median over all the pairs of regions, then the kinds averaged, so that every kind weighs alike
    however spread its values (the curvedness at large radii varies little, and would otherwise
    count for little); a distance of 1 is then a typical one. False: the weighted mean over all
    the histograms, in [0, 1].
    threads: how many threads share the rows (default: the CPUs)."""
    return _native.histogram_distances(a, b, bool(balance), _threads(threads))


def chi_square_distances(a, b):
    """(len(a), len(b)) chi-square distances 1/2 sum (x - y)^2 / (x + y) between rows of
    histograms (0/0 terms count 0); divided by the number of histograms when rows are
    concatenations of normalised histograms, the distance lies in [0, 1]."""
    a = np.asarray(a, dtype=np.float64)
    b = np.asarray(b, dtype=np.float64)
    out = np.empty((len(a), len(b)))
    chunk = max(1, 4_000_000 // max(1, len(b) * a.shape[1]))
    for start in range(0, len(a), chunk):
        x = a[start:start + chunk, None, :]
        total = x + b[None, :, :]
        diff = x - b[None, :, :]
        with np.errstate(invalid="ignore", divide="ignore"):
            terms = np.where(total > 0, diff * diff / np.where(total > 0, total, 1), 0)
        out[start:start + chunk] = 0.5 * terms.sum(axis=2)
    return out


def fit_rigid(source, target, weights=None):
    """The rotation R and translation t minimising sum w |R source + t - target|^2 (Kabsch, a proper
    rotation): (R (3, 3), t (3,))."""
    source, target = _points(source, "source"), _points(target, "target")
    if weights is not None:
        weights = np.ascontiguousarray(weights, dtype=np.float64)
    return _native.fit_rigid(source, target, weights)


def register_correspondences(source, target, *, tolerance=3.0, iterations=2000, seed=0):
    """A rigid motion placing ``source`` points onto their ``target`` points, robust to wrong pairs.

    RANSAC: triples of pairs whose mutual distances agree within
    ``tolerance`` on both sides give candidate motions; the one under which
    most pairs land within ``tolerance`` wins, then is refitted by least
    squares on those pairs (twice). Returns (R, t, inliers), inliers a
    boolean array over the pairs.
    """
    source, target = _points(source, "source"), _points(target, "target")
    return _native.register_correspondences(source, target, float(tolerance), int(iterations), int(seed))


class Matches:
    """The best candidates of B for each region of A, and the registration of B onto A.

    Attributes:
        centers: (M,) A's centre point indices; candidates: (M, top) B's
            point indices, best first by ``histogram_distances``; scores:
            (M, top) those distances (0 identical, smaller is better).
        rotation, translation: the rigid motion x -> R x + t placing B onto A.
        inliers: (M,) whether each centre's best candidate agrees with the
            registration (within the tolerance); consistent: their share.
        reranked: (M, top) B's point indices re-ranked by the registration:
            among each centre's ``pool`` best candidates, those the motion
            places within the tolerance of the centre first, then the others,
            each group in the order of the descriptors.
    """

    def __init__(self, centers, candidates, scores, rotation, translation, inliers, reranked):
        self.centers = centers
        self.candidates = candidates
        self.scores = scores
        self.rotation = rotation
        self.translation = translation
        self.inliers = inliers
        self.reranked = reranked
        self.consistent = float(np.mean(inliers)) if len(inliers) else 0.0

    def transform(self, points):
        """B's points placed onto A."""
        return np.asarray(points, dtype=np.float64) @ self.rotation.T + self.translation

    def __repr__(self):
        return f"<Matches: {len(self.centers)} regions, {self.consistent:.0%} consistent with the registration>"


def match_regions(a, b, *, top=10, pool=50, tolerance=3.0, iterations=2000, seed=0, threads=None, balance=True):
    """The best candidates among B's regions for each of A's, and the registration of B onto A.

    Parameters:
        a, b: ``Regions`` of the two surfaces, made with the same rings,
            bins, weights and layers (the same radii, in the same units).
        top: candidates kept per region of A.
        pool: the best candidates per region of A that the re-ranking by the
            registration chooses from (at least ``top``).
        tolerance: the registration's inlier distance (model units).
        iterations, seed: of the RANSAC.
        threads, balance: of ``histogram_distances``.

    Returns:
        ``Matches``.
    """
    if len(b) == 0 or len(a) == 0:
        raise ValueError("match_regions: no region")
    candidates, scores, rotation, translation, inliers, reranked = _native.match_regions(
        a, b, int(top), int(pool), float(tolerance), int(iterations), int(seed), _threads(threads), bool(balance))
    return Matches(a.centers, candidates, scores, rotation, translation, inliers, reranked)
