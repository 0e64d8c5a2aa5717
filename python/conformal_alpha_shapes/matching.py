"""Shape descriptors of surface regions, and matching them from one surface to another.

numpy only. Lengths are in the units of the points; curvatures in inverse units.

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

import concurrent.futures
import math
import os

import numpy as np

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
    count = len(points)
    if n >= count:
        return np.arange(count)
    chosen = np.empty(n, dtype=np.int64)
    chosen[0] = first
    distance = np.sum((points - points[first]) ** 2, axis=1)
    for i in range(1, n):
        chosen[i] = int(np.argmax(distance))
        np.minimum(distance, np.sum((points - points[chosen[i]]) ** 2, axis=1), out=distance)
    return chosen


def _layer_values(layers):
    """The (shape index, curvedness x radius) of every point at every layer: two (N, L) arrays."""
    if hasattr(layers, "layers") and hasattr(layers, "__getitem__") and not isinstance(layers, (list, tuple)):
        layers = [layers[name] for name in layers.layers]
    if isinstance(layers, dict) or hasattr(layers, "k1"):
        layers = [layers]
    s, c = [], []
    for layer in layers:
        k1 = np.asarray(layer["k1"], dtype=np.float64)
        k2 = np.asarray(layer["k2"], dtype=np.float64)
        radius = np.asarray(layer["radius"], dtype=np.float64)
        s.append(shape_index(k1, k2))
        # curvedness without unit: times the fit's radius (about 1 on a sphere as large as the fit)
        c.append(curvedness(k1, k2) * radius)
    if not s:
        raise ValueError("region_descriptors: no curvature layer")
    return np.column_stack(s), np.column_stack(c)


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
    s, c = _layer_values(layers)
    if len(s) != len(points):
        raise ValueError(f"region_descriptors: {len(points)} points but {len(s)} values per layer")
    rings = np.asarray(rings, dtype=np.float64)
    if rings.ndim != 1 or len(rings) == 0 or not np.all(rings > 0) or np.any(np.diff(rings) <= 0):
        raise ValueError("region_descriptors: rings must be increasing radii > 0")
    if int(thinning) != thinning or thinning < 1 or not dense_radius > 0:
        raise ValueError("region_descriptors: thinning must be an integer >= 1 and dense_radius > 0")
    thinning = int(thinning)
    if shape_bins < 2 or curvedness_bins < 1 or geometry_bins < 2:
        raise ValueError("region_descriptors: at least 2 shape index and geometry bins and 1 curvedness bin")
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
    if normals is not None:
        normals = _unit(normals, "normals", len(points))
        center_normals = normals if center_normals is None else _unit(center_normals, "center_normals",
                                                                      len(points))
    n_rings, n_layers = len(rings), s.shape[1]
    per_layer = shape_bins + curvedness_bins
    geometry = 0 if normals is None else 2 * geometry_bins
    per_ring = n_layers * per_layer + geometry
    width = n_rings * per_ring
    defined = np.isfinite(s) & np.isfinite(c)
    s0, sw0, s1, sw1 = _soft_bins(np.nan_to_num(s), -1.0, 1.0, shape_bins)
    c0, cw0, c1, cw1 = _soft_bins(np.nan_to_num(c), 0.0, curvedness_range, curvedness_bins)
    layer_offset = np.arange(n_layers) * per_layer
    # per point and layer: the four (bin, weight) contributions within a ring's block
    bins_of = np.concatenate([s0 + layer_offset, s1 + layer_offset, c0 + layer_offset + shape_bins,
                              c1 + layer_offset + shape_bins], axis=1)
    weights_of = np.concatenate([sw0, sw1, cw0, cw1], axis=1) * np.tile(defined, 4)
    descriptors = np.zeros((len(centers), width))
    squares = np.sum(points ** 2, axis=1)
    outer2 = rings[-1] ** 2
    dense2 = min(dense_radius, rings[-1]) ** 2 if thinning > 1 else outer2
    kept = np.arange(0, len(points), thinning)  # the points that count beyond dense_radius
    chunk = max(1, 1_000_000 // max(1, len(points)))
    def describe(start):
        block = centers[start:start + chunk]
        d2 = squares[block][:, None] - 2 * points[block] @ points.T + squares[None, :]
        row, near = np.nonzero(d2 <= dense2)
        if thinning > 1 and dense2 < outer2:
            far_row, far = np.nonzero((d2[:, kept] > dense2) & (d2[:, kept] <= outer2))
            row, near = np.concatenate([row, far_row]), np.concatenate([near, kept[far]])
        ring = np.searchsorted(rings ** 2, d2[row, near], side="left")  # d2 <= outer2: always a ring
        base = (row * width + ring * per_ring)[:, None]
        # np.take: faster than fancy indexing for whole rows
        index = [(base + np.take(bins_of, near, axis=0)).ravel()]
        values = [np.take(weights_of, near, axis=0).ravel()]
        if normals is not None:
            axis = center_normals[block][row]
            cosine = np.einsum("ij,ij->i", normals[near], axis)
            height = np.einsum("ij,ij->i", points[near] - points[block][row], axis) / rings[ring]
            offset = base[:, 0] + n_layers * per_layer
            for k, v in enumerate((cosine, height)):
                i0, w0, i1, w1 = _soft_bins(v, -1.0, 1.0, geometry_bins)
                index += [offset + k * geometry_bins + i0, offset + k * geometry_bins + i1]
                values += [w0, w1]
        descriptors[start:start + len(block)] = np.bincount(
            np.concatenate(index), weights=np.concatenate(values), minlength=len(block) * width).reshape(-1, width)

    _run(describe, range(0, len(centers), chunk), threads)
    # each histogram normalised to sum 1
    histogram_bins = np.tile([shape_bins, curvedness_bins] * n_layers + [geometry_bins] * (2 if geometry else 0),
                             n_rings).astype(np.int64)
    histogram_weights = np.repeat(ring_weights, len(histogram_bins) // n_rings)
    histogram_kinds = np.tile(np.arange(len(histogram_bins) // n_rings), n_rings)
    ends = np.cumsum(histogram_bins)
    for first, end in zip(ends - histogram_bins, ends):
        part = descriptors[:, first:end]
        total = part.sum(axis=1, keepdims=True)
        np.divide(part, total, out=part, where=total > 0)
    return Regions(points, centers, descriptors, rings, (shape_bins, curvedness_bins), histogram_bins,
                   histogram_weights, histogram_kinds)


def _cumulative(regions):
    """Rows whose L1 distances are ``histogram_distances``: each histogram's running sums, weighted."""
    x = regions.descriptors
    ends = np.cumsum(regions.histogram_bins)
    out = np.empty_like(x)
    scale = regions.histogram_weights / regions.histogram_bins / regions.histogram_weights.sum()
    for first, end, w in zip(ends - regions.histogram_bins, ends, scale):
        np.cumsum(x[:, first:end], axis=1, out=out[:, first:end])
        out[:, first:end] *= w
    return out


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
    if (a.descriptors.shape[1] != b.descriptors.shape[1] or a.rings != b.rings or a.bins != b.bins
            or not np.array_equal(a.histogram_bins, b.histogram_bins)
            or not np.array_equal(a.histogram_weights, b.histogram_weights)
            or not np.array_equal(a.histogram_kinds, b.histogram_kinds)):
        raise ValueError("histogram_distances: the regions were described with different layouts")
    # float32 halves the memory traffic; the sums keep about 6 digits, far below the distances' spread
    x, y = _cumulative(a).astype(np.float32), _cumulative(b).astype(np.float32)
    if not balance:
        return _l1(x, y, threads)
    column_kind = np.repeat(a.histogram_kinds, a.histogram_bins)
    kinds = np.unique(a.histogram_kinds)
    out = np.zeros((len(x), len(y)))
    for kind in kinds:
        columns = np.nonzero(column_kind == kind)[0]
        d = _l1(np.ascontiguousarray(x[:, columns]), np.ascontiguousarray(y[:, columns]), threads)
        median = float(np.median(d))
        out += d / median if median > 0 else d
    return out / len(kinds)


def _l1(x, y, threads):
    """(len(x), len(y)) L1 distances between rows."""
    out = np.empty((len(x), len(y)))
    chunk = max(1, 2_000_000 // max(1, len(y) * x.shape[1]))

    def rows(start):
        out[start:start + chunk] = np.abs(x[start:start + chunk, None, :] - y[None, :, :]).sum(axis=2)

    _run(rows, range(0, len(x), chunk), threads)
    return out


def _run(function, starts, threads):
    """function(start) for every start, on ``threads`` threads (default: the CPUs): numpy lets go of
    the GIL in its large operations, so threads share the work."""
    threads = (os.cpu_count() or 1) if threads is None else threads
    if threads > 1 and len(starts) > 1:
        with concurrent.futures.ThreadPoolExecutor(max_workers=threads) as pool:
            list(pool.map(function, starts))
    else:
        for start in starts:
            function(start)


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
    source = np.asarray(source, dtype=np.float64)
    target = np.asarray(target, dtype=np.float64)
    w = np.ones(len(source)) if weights is None else np.asarray(weights, dtype=np.float64)
    w = w / w.sum()
    cs = w @ source
    ct = w @ target
    h = ((source - cs) * w[:, None]).T @ (target - ct)
    u, _, vt = np.linalg.svd(h)
    d = np.sign(np.linalg.det(vt.T @ u.T))
    r = vt.T @ np.diag([1.0, 1.0, d]) @ u.T
    return r, ct - r @ cs


def register_correspondences(source, target, *, tolerance=3.0, iterations=2000, seed=0):
    """A rigid motion placing ``source`` points onto their ``target`` points, robust to wrong pairs.

    RANSAC: triples of pairs whose mutual distances agree within
    ``tolerance`` on both sides give candidate motions; the one under which
    most pairs land within ``tolerance`` wins, then is refitted by least
    squares on those pairs (twice). Returns (R, t, inliers), inliers a
    boolean array over the pairs.
    """
    source = _points(source, "source")
    target = _points(target, "target")
    n = len(source)
    if n < 3:
        raise ValueError("register_correspondences: fewer than 3 pairs")
    rng = np.random.default_rng(seed)
    # all the triples at once: those of three distinct pairs, spread and of equal shapes on both sides
    triples = rng.integers(0, n, size=(iterations, 3))
    triples = triples[(triples[:, 0] != triples[:, 1]) & (triples[:, 0] != triples[:, 2])
                      & (triples[:, 1] != triples[:, 2])]
    s3, t3 = source[triples], target[triples]
    ds = np.linalg.norm(s3[:, [0, 0, 1]] - s3[:, [1, 2, 2]], axis=2)
    dt = np.linalg.norm(t3[:, [0, 0, 1]] - t3[:, [1, 2, 2]], axis=2)
    keep = (np.max(np.abs(ds - dt), axis=1) <= tolerance) & (np.min(ds, axis=1) >= tolerance)
    s3, t3 = s3[keep], t3[keep]
    if len(s3):
        # Kabsch on every triple
        cs, ct = s3.mean(axis=1), t3.mean(axis=1)
        h = np.einsum("kia,kib->kab", s3 - cs[:, None], t3 - ct[:, None])
        u, _, vt = np.linalg.svd(h)
        d = np.sign(np.linalg.det(np.einsum("kba,kcb->kac", vt, u)))
        u[:, :, 2] *= d[:, None]
        rotations = np.einsum("kba,kcb->kac", vt, u)
        translations = ct - np.einsum("kab,kb->ka", rotations, cs)
        counts = np.empty(len(s3), dtype=np.int64)
        for start in range(0, len(s3), 256):
            r, t = rotations[start:start + 256], translations[start:start + 256]
            placed = np.einsum("kab,nb->kna", r, source) + t[:, None, :]
            counts[start:start + 256] = np.sum(np.linalg.norm(placed - target, axis=2) < tolerance, axis=1)
        best = int(np.argmax(counts))
        r, t = rotations[best], translations[best]
    else:
        r, t = fit_rigid(source, target)
    inliers = np.linalg.norm(source @ r.T + t - target, axis=1) < tolerance
    for _ in range(2):
        if inliers.sum() >= 3:
            r, t = fit_rigid(source[inliers], target[inliers])
            inliers = np.linalg.norm(source @ r.T + t - target, axis=1) < tolerance
    return r, t, inliers


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
    try:
        distances = histogram_distances(a, b, threads, balance)
    except ValueError:
        raise ValueError("match_regions: the regions were described with different layouts") from None
    top = min(top, len(b))
    pool = min(max(pool, top), len(b))
    order = np.argsort(distances, axis=1, kind="stable")[:, :pool]
    scores = np.take_along_axis(distances, order[:, :top], axis=1)
    candidates = b.centers[order]
    rotation, translation, inliers = register_correspondences(
        b.points[candidates[:, 0]], a.points[a.centers], tolerance=tolerance, iterations=iterations, seed=seed) \
        if len(a) >= 3 else (np.eye(3), np.zeros(3), np.zeros(len(a), dtype=bool))
    # the registration's verdict on each candidate of the pool; a stable sort keeps the descriptors' order
    placed = b.points[candidates] @ rotation.T + translation
    agree = np.linalg.norm(placed - a.points[a.centers][:, None, :], axis=2) < tolerance
    reranked = np.take_along_axis(candidates, np.argsort(~agree, axis=1, kind="stable"), axis=1)[:, :top]
    return Matches(a.centers, candidates[:, :top], scores, rotation, translation, inliers, reranked)
