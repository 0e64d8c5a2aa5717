"""The seam orientation: each tile's objects vote on the halo points they
share with their neighbor tiles, the driver chooses the objects to turn over
so that neighbors agree, and the workers rewrite those parts turned."""

import os

import numpy as np

from . import tile_io, tile_partition

# Shared points below which a seam does not vote (a corner touching a halo).
MINIMUM_SEAM_POINTS = 20
# With input normals, an object of a tile follows them when at least this
# share of its points' normals agree with them: its tile's sheets followed
# the normals. Below it (about half, for normals of random signs, which the
# tile recognized per sheet) it is oriented as without normals.
FOLLOWED_SHARE = 0.75
# One run's rule for a group of open sheets whose cones nearly cancel (a
# terrain): below this share of the sum of its terms' sizes the cone does not
# decide, and the group faces +z if its area normals summed reach
# MOSTLY_ALONG_Z_SHARE of its area (C++: nearly_flat_cone_share and
# mostly_along_z_share in internal/orient_surface_parts.h).
NEARLY_FLAT_CONE_SHARE = 0.25
MOSTLY_ALONG_Z_SHARE = 0.5


def tile_votes(folder, tile, names, first_names, states):
    """Votes of a tile's halo points against their owners' parts, both taken
    unflipped (``states``: per tile and scale, the objects its part carries
    turned): ``[(scale, this tile's object, owner, its object, agree, disagree)]``."""
    seam = np.load(os.path.join(folder, "tiles", f"seam_{tile:05d}.npy"))
    votes = []
    for owner in np.unique(seam["owner"]):
        owner = int(owner)
        mine = seam[seam["owner"] == owner]
        part = tile_io.read_part(tile_partition.part_path(folder, owner), names)
        rows = np.searchsorted(part["input_index"].astype(np.int64), mine["index"])
        theirs_objects = np.load(tile_partition.tile_path(folder, owner, "objects.npy"))[:, rows]
        for s, name in enumerate(first_names):
            theirs = np.column_stack([part[f"n{axis}_{name}"][rows] for axis in "xyz"]).astype(np.float64)
            sign = np.where(np.isin(theirs_objects[s], states[owner][s]), -1.0, 1.0)
            dot = sign * np.einsum("ij,ij->i", theirs, mine["normal"][:, s, :].astype(np.float64))
            valid = np.isfinite(dot) & (dot != 0)
            pairs = np.column_stack([mine["object"][valid, s], theirs_objects[s][valid]])
            for (a, b), count in zip(*np.unique(pairs, axis=0, return_counts=True)):
                both = valid.copy()
                both[valid] = (pairs[:, 0] == a) & (pairs[:, 1] == b)
                votes.append((s, int(a), owner, int(b), int((dot[both] > 0).sum()), int((dot[both] < 0).sum())))
    return votes


def _flip_layer(records, name, rows):
    """The values of layer ``name`` at ``rows`` as seen from the other side of the surface."""
    for axis in ("x", "y", "z"):
        records[f"n{axis}_{name}"][rows] *= -1
        d1, d2 = records[f"d1{axis}_{name}"][rows], records[f"d2{axis}_{name}"][rows]
        records[f"d1{axis}_{name}"][rows], records[f"d2{axis}_{name}"][rows] = d2, d1
    records[f"H_{name}"][rows] *= -1
    k1, k2 = records[f"k1_{name}"][rows], records[f"k2_{name}"][rows]
    records[f"k1_{name}"][rows], records[f"k2_{name}"][rows] = -k2, -k1


def tile_flip(folder, tile, names, scale_layers, turns):
    """Rewrites a part with the layers of each scale ``s`` turned over at the
    points of the objects ``turns[s]`` (which toggle what the part carries)."""
    path = tile_partition.part_path(folder, tile)
    header = tile_io.part_header(path)
    records = np.array(tile_io.read_part(path, names))
    of_points = np.load(tile_partition.tile_path(folder, tile, "objects.npy"))
    for s, objects in turns.items():
        rows = np.flatnonzero(np.isin(of_points[s], objects))
        for name in scale_layers[s]:
            _flip_layer(records, name, rows)

    def write(temporary):
        with open(temporary, "wb") as f:
            f.write(header)
            records.tofile(f)
    tile_io.atomic_write(path, write)
    return {"size": os.path.getsize(path), "sha256": tile_io.file_digest(path)}


def not_following_normals(parts, s, small=False):
    """The objects (tile, object) of a run with input normals whose points'
    normals at scale ``s`` agree with the input's below ``FOLLOWED_SHARE``;
    with ``small``, also those with too few points on the surface to tell."""
    free = set()
    for t, part in enumerate(parts):
        if len(part.get("agreement", [])) > s:
            agree, total = part["agreement"][s]
            free |= {(t, c) for c in range(len(total))
                     if (small and total[c] < MINIMUM_SEAM_POINTS)
                     or (total[c] >= MINIMUM_SEAM_POINTS and agree[c] < FOLLOWED_SHARE * total[c])}
    return free


def _surface_center(parts, s):
    """The center of the surface's vertices at scale ``s`` (from the run's
    center, as the tiles' votes are), the apex of one run's cones."""
    total = sum(np.asarray(part["votes"][s]["vertex_sum"]) for part in parts)
    count = sum(part["votes"][s]["vertex_count"] for part in parts)
    return total / count if count else np.zeros(3)


def _group_vote(parts, s, group, relative, center):
    """The side that a group of objects faces at scale ``s``, by its sign, as
    one run's vote over their faces: the cone it spans from the surface's
    ``center``, or where that nearly cancels and the group mostly faces
    along z, its area normals' z summed. The cones' sizes are taken from
    the run's center rather than the surface's (a tile does not know the
    latter when it sums them), which can move the rule of nearly flat cones
    only for a group at its threshold."""
    def summed(key, signed):
        return sum(-parts[t]["votes"][s][key][c] if signed and relative[(t, c)] else parts[t]["votes"][s][key][c]
                   for t, c in group)

    def cone_of(t, c):
        votes = parts[t]["votes"][s]
        return votes["cone"][c] - sum(center[k] * votes["normal"][k][c] for k in range(3))
    cone = sum(-cone_of(t, c) if relative[(t, c)] else cone_of(t, c) for t, c in group)
    up = summed("up", True)
    if abs(cone) < NEARLY_FLAT_CONE_SHARE * summed("cone_size", False) \
            and abs(up) >= MOSTLY_ALONG_Z_SHARE * summed("area", False):
        return up
    return cone


def orient(votes, parts, scales, has_normals):
    """Per tile and scale, the objects (``tile_partition.surface_objects``) its
    part is to carry turned over: an object is turned when its seam to the
    object it was reached from votes to disagree (from the largest object, by
    the strongest seams); each group of objects so joined faces as one run's
    vote over their faces says (away from the surface's center: outward for
    a closed sheet; up where that nearly cancels and the group faces mostly
    along z). With
    input normals, nothing is turned where every object follows them
    (``FOLLOWED_SHARE``); otherwise those that do are never turned and the
    others (small ones too) are joined to them by their seams first."""
    turned = [[[] for _ in range(scales)] for _ in parts]
    for s in range(scales):
        units = [(t, c) for t, part in enumerate(parts) for c in range(len(part["sizes"][s]))]

        def size(unit):
            return -parts[unit[0]]["sizes"][s][unit[1]]
        center = _surface_center(parts, s)
        if has_normals and not not_following_normals(parts, s):
            continue  # every object follows the normals: none is turned
        free = not_following_normals(parts, s, small=True) if has_normals else set(units)
        fixed = [unit for unit in units if unit not in free]
        edges = {}
        for t, ballots in votes.items():
            for scale, mine, owner, theirs, agree, disagree in ballots:
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
        relative = {unit: False for unit in fixed}
        roots = sorted(fixed, key=size) + sorted([unit for unit in units if unit in free], key=size)
        for root in roots:
            if root in relative and root in free:
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
            if root not in free:  # the objects that follow the normals decide
                for t, c in group:
                    if relative[(t, c)]:
                        turned[t][s].append(c)
                continue
            cone = _group_vote(parts, s, group, relative, center)
            for t, c in group:
                if relative[(t, c)] ^ (cone < 0):
                    turned[t][s].append(c)
    return turned
