#!/usr/bin/python3
"""The manual's figure of region matching: a region of 1HPV chain A and its best matches on chain B.

Both chains' surfaces, their curvature and the descriptors are those of
benchmark_matching.py (spacing 0.4 A, radii 1.5 to 12 A, rings 0-2 to
12-14 A, the r3 layer's normal as the centres'). The region is the most
concave one at 6 A among the benchmark's 300 farthest-point centres of A
(the lowest shape index of the r6 layer: a pocket). Its descriptor distance
(histogram_distances) to the region around every point of B colours B;
B is placed in A's frame by match_regions' registration (the benchmark's
300 centres against 2,000 candidates), so both panels share one view, from
A's centroid towards the region. The true place of the region on B (CA
atoms superposed, which the matcher never sees) and B's best point are
marked. It prints what it measured and writes a small PNG.

Usage:
  matching_figure.py --build BUILD_DIR [--work DIR] [--output PNG]
BUILD_DIR as for benchmark_matching.py. Needs pymol-data and python3-matplotlib.
"""

import argparse
import io
import os
import sys

import numpy as np

import benchmark_matching as bench

DEFAULT_OUTPUT = os.path.join(bench.SOURCE_DIR, "doc", "Conformal_alpha_shapes_3", "fig", "1hpv_match.png")
REGION_RADIUS = bench.RINGS[-1]


def view_basis(points, centre):
    """Rows u, v, w: w from the centroid of the points towards the centre (towards the viewer)."""
    w = centre - points.mean(axis=0)
    w /= np.linalg.norm(w)
    u = np.cross([0.0, 0.0, 1.0], w) if abs(w[2]) < 0.9 else np.cross([1.0, 0.0, 0.0], w)
    u /= np.linalg.norm(u)
    return np.array([u, np.cross(w, u), w])


def draw(ax, basis, points, colours, title):
    """The points projected on the view plane, the nearest drawn last so they hide the ones behind."""
    xyz = points @ basis.T
    order = np.argsort(xyz[:, 2])
    ax.scatter(xyz[order, 0], xyz[order, 1], c=colours[order], s=10, marker="o", linewidths=0)
    ax.set_title(title, fontsize=10)
    ax.set_aspect("equal")
    ax.set_axis_off()


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--build", required=True)
    parser.add_argument("--work", default="benchmark_matching_work")
    parser.add_argument("--output", default=DEFAULT_OUTPUT)
    args = parser.parse_args()
    sys.path.insert(0, os.path.join(os.path.abspath(args.build), "python"))
    from conformal_alpha_shapes import matching as m
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    from PIL import Image

    if not os.path.exists(bench.HPV):
        sys.exit(f"{bench.HPV} is missing: install pymol-data (apt-get install pymol-data)")
    os.makedirs(args.work, exist_ok=True)
    pa, na, va, _ = bench.surface(args.build, args.work, bench.HPV, "A")
    pb, nb, vb, _ = bench.surface(args.build, args.work, bench.HPV, "B")
    la, ca_normals = bench.layers_from_ply(va)
    lb, cb_normals = bench.layers_from_ply(vb)
    centres = m.farthest_point_sample(pa, bench.CENTRES)
    ra = m.region_descriptors(pa, la, centres, normals=na, center_normals=ca_normals, rings=bench.RINGS)
    rb = m.region_descriptors(pb, lb, m.farthest_point_sample(pb, bench.CANDIDATES), normals=nb,
                              center_normals=cb_normals, rings=bench.RINGS)
    matches = m.match_regions(ra, rb, top=10)

    r6 = la[bench.RADII.index(6.0)]
    shape6 = m.shape_index(r6["k1"][centres], r6["k2"][centres])
    chosen = int(centres[np.nanargmin(shape6)])
    region = m.region_descriptors(pa, la, np.array([chosen]), normals=na, center_normals=ca_normals,
                                  rings=bench.RINGS)
    everywhere = m.region_descriptors(pb, lb, None, normals=nb, center_normals=cb_normals, rings=bench.RINGS)
    distance = m.histogram_distances(region, everywhere)[0]

    ca_a, ca_b = bench.common_ca_atoms(bench.HPV, "A", "B")
    r_true, t_true = m.fit_rigid(ca_a, ca_b)  # A onto B
    true_place = pa[chosen] @ r_true.T + t_true
    best = int(np.argmin(distance))
    rank = int(np.sum(distance < distance[np.argmin(np.linalg.norm(pb - true_place, axis=1))])) + 1
    near_true = np.linalg.norm(pb - true_place, axis=1) <= bench.HIT
    print(f"region: A's point {chosen}, shape index at 6 A {np.nanmin(shape6):.3f} (the lowest of "
          f"{len(centres)} centres); registration {matches.consistent:.0%} consistent")
    print(f"B's best point is {np.linalg.norm(pb[best] - true_place):.2f} A from the true place; "
          f"B's point nearest the true place ranks {rank} of {len(pb)}; distances within {bench.HIT:g} A "
          f"of it {distance[near_true].min():.3f} to {distance[near_true].max():.3f}, median over B "
          f"{np.median(distance):.3f}")

    placed = matches.transform(pb)
    basis = view_basis(pa, pa[chosen])
    shade_a = 0.45 + 0.45 * np.clip(na @ basis[2], 0, 1)
    colours_a = np.repeat(shade_a[:, None], 3, axis=1)
    inside = np.linalg.norm(pa - pa[chosen], axis=1) <= REGION_RADIUS
    colours_a[inside] = np.array([0.95, 0.45, 0.1]) * (0.5 + 0.5 * shade_a[inside, None])
    low, high = distance.min(), np.percentile(distance, 75)
    colours_b = plt.get_cmap("viridis")(1 - np.clip((distance - low) / (high - low), 0, 1))[:, :3]
    colours_b *= (0.8 + 0.2 * np.clip((nb @ matches.rotation.T) @ basis[2], 0, 1))[:, None]

    figure, axes = plt.subplots(1, 2, figsize=(9, 4.5), dpi=100)
    draw(axes[0], basis, pa, colours_a, f"1HPV chain A: the region (orange, {REGION_RADIUS:g} A)")
    draw(axes[1], basis, placed, colours_b, "chain B placed on A: descriptor distance (bright = close)")
    for ax, point in ((axes[0], pa[chosen]), (axes[1], matches.transform(true_place))):
        x, y, _ = basis @ point
        ax.plot(x, y, marker="o", markersize=11, markerfacecolor="none", markeredgecolor="black", markeredgewidth=2)
    x, y, _ = basis @ placed[best]
    axes[1].plot(x, y, marker="+", markersize=20, color="red", markeredgewidth=2.5)
    figure.subplots_adjust(left=0.01, right=0.99, bottom=0.01, top=0.93, wspace=0.02)
    buffer = io.BytesIO()
    figure.savefig(buffer, format="png")
    buffer.seek(0)
    image = Image.open(buffer).convert("RGB").quantize(colors=128)  # a palette keeps the PNG small
    temporary = args.output + ".partial.png"
    image.save(temporary, optimize=True)
    os.replace(temporary, args.output)
    print(f"{args.output}: {image.size[0]}x{image.size[1]} px, {os.path.getsize(args.output)} bytes")


if __name__ == "__main__":
    main()
