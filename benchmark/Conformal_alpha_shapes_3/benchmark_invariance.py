#!/usr/bin/python3
"""One run's default job on a cloud and on copies that sample the same
surface: translated by 1e-7 and 1e-4 of the bounding box's diagonal, scaled
by 3, turned by 90 degrees about z, 5% of the points written twice, the
points in reverse order. Prints a row per cloud and change: the relative
change of `a`, of the spacing (over the scaling) and of the noise, in
percent, and over the layers the smallest share of points whose normal
stays on the same side and the largest median relative change of H (H
times the scaling), in percent (the manual, "Input Rules").

    PYTHONPATH=build/python /usr/bin/python3 benchmark/Conformal_alpha_shapes_3/benchmark_invariance.py \\
        FILE [FILE ...] [--csv FILE]

The values are the module's `multiscale_curvatures` with its defaults.
"""
import argparse
import os
import sys

import numpy as np

import conformal_alpha_shapes as cas

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import cas3_benchmark  # noqa: E402


def changes(points, normals):
    """Each change: (name, points, normals, scaling, the rows of the original
    points, the turn of the normals)."""
    diagonal = float(np.linalg.norm(points.max(axis=0) - points.min(axis=0)))
    turn = np.array([[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]])
    twice = np.random.default_rng(1).choice(len(points), len(points) // 20, replace=False)
    every = np.arange(len(points))
    yield "translated 1e-7", points + 1e-7 * diagonal, normals, 1.0, every, None
    yield "translated 1e-4", points + 1e-4 * diagonal, normals, 1.0, every, None
    yield "scaled by 3", points * 3, normals, 3.0, every, None
    yield "turned 90 deg about z", points @ turn.T, None if normals is None else normals @ turn.T, 1.0, every, turn
    yield "5% written twice", np.vstack([points, points[twice]]), \
        None if normals is None else np.vstack([normals, normals[twice]]), 1.0, every, None
    yield "reverse order", points[::-1], None if normals is None else normals[::-1], 1.0, every[::-1], None


def layer_changes(base, moved, rows, scaling, turn):
    """Over the layers: the smallest share of normals on the same side, the
    largest median relative change of H (in percent)."""
    same, change = 1.0, 0.0
    for name in base.layers:
        normal = moved[name].normal[rows] if turn is None else moved[name].normal[rows] @ turn
        H0, H1 = base[name].H, moved[name].H[rows] * scaling
        dot = np.einsum("ij,ij->i", base[name].normal, normal)
        valid = np.isfinite(dot) & np.isfinite(H0) & np.isfinite(H1)
        same = min(same, float(np.mean(dot[valid] > 0)))
        change = max(change, 100 * float(np.median(np.abs(H1[valid] - H0[valid])) / np.median(np.abs(H0[valid]))))
    return same, change


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("inputs", nargs="+")
    parser.add_argument("--csv", help="also write the rows to this CSV file")
    args = parser.parse_args()
    rows = []
    for path in args.inputs:
        read = cas.read_point_cloud(path)
        points, normals = read if isinstance(read, tuple) else (read, None)
        base = cas.multiscale_curvatures(points, normals)
        a, spacing, noise = base["rauto"].a, base.spacing, base.noise
        print(f"{os.path.basename(path)}: {len(points)} points, a {a:.6g}, spacing {spacing:.6g}, noise {noise:.4g}")
        for name, moved, moved_normals, scaling, rows_of, turn in changes(points, normals):
            result = cas.multiscale_curvatures(moved, moved_normals)
            same, change = layer_changes(base, result, rows_of, scaling, turn)
            row = {"input": os.path.basename(path), "change": name,
                   "a_percent": 100 * (result["rauto"].a / a - 1),
                   "spacing_percent": 100 * (result.spacing / scaling / spacing - 1),
                   "noise_percent": 100 * (result.noise / noise - 1),
                   "same_side_percent": 100 * same, "H_change_percent": change}
            rows.append(row)
            print(f"  {name:24s} a {row['a_percent']:+.3f}%  spacing {row['spacing_percent']:+.3f}%  "
                  f"noise {row['noise_percent']:+.3f}%  same side {row['same_side_percent']:.2f}%  "
                  f"H change {change:.4f}%", flush=True)
    if args.csv:
        cas3_benchmark.write_csv(args.csv, ["input", "change", "a_percent", "spacing_percent", "noise_percent",
                                          "same_side_percent", "H_change_percent"], rows)


if __name__ == "__main__":
    main()
