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
# decide, and the group faces +z if its normals summed reach
# MOSTLY_ALONG_Z_SHARE of their count (C++: nearly_flat_cone_share and
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
        theirs_component = np.load(tile_partition.tile_path(folder, owner, "component.npy"))[rows]
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
    component = np.load(tile_partition.tile_path(folder, tile, "component.npy"))
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


def _group_vote(parts, s, group, relative):
    """The side that a group of objects faces at scale ``s``, by its sign: the
    cone it spans from the cloud's center, or where that nearly cancels and
    the group mostly faces along z, its normals' z summed (one run's rule)."""
    def summed(key, signed):
        return sum(-parts[t][key][s][c] if signed and relative[(t, c)] else parts[t][key][s][c] for t, c in group
                   if key in parts[t])
    cone, up = summed("cones", True), summed("up", True)
    if abs(cone) < NEARLY_FLAT_CONE_SHARE * summed("cone_sizes", False) \
            and abs(up) >= MOSTLY_ALONG_Z_SHARE * summed("counts", False):
        return up
    return cone


def orient(votes, parts, scales, has_normals):
    """Per tile and scale, the objects (``tile_partition.components``) its
    part is to carry turned over: an object is turned when its seam to the
    object it was reached from votes to disagree (from the largest object, by
    the strongest seams); each group of objects so joined faces away from the
    cloud's center, as one run's sheets do (outward for a closed one; up
    where that nearly cancels and the group faces mostly along z). With
    input normals, nothing is turned where every object follows them
    (``FOLLOWED_SHARE``); otherwise those that do are never turned and the
    others (small ones too) are joined to them by their seams first."""
    turned = [[[] for _ in range(scales)] for _ in parts]
    units = [(t, c) for t, part in enumerate(parts) for c in range(len(part["sizes"]))]

    def size(unit):
        return -parts[unit[0]]["sizes"][unit[1]]
    for s in range(scales):
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
            cone = _group_vote(parts, s, group, relative)
            for t, c in group:
                if relative[(t, c)] ^ (cone < 0):
                    turned[t][s].append(c)
    return turned
