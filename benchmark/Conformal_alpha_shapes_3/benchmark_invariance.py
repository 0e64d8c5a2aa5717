#!/usr/bin/python3
"""One run's automatic scale, spacing and noise on a cloud and on copies that
sample the same surface: translated by 1e-7 and 1e-4 of the bounding box's
diagonal, scaled by 3, turned by 90 degrees about z, 5% of the points
written twice, the points in reverse order. Prints a row per cloud and
change: the relative change of `a`, of the spacing (over the scaling) and of
the noise, in percent (the manual, "Input Rules").

    PYTHONPATH=build/python /usr/bin/python3 benchmark/Conformal_alpha_shapes_3/benchmark_invariance.py \\
        FILE [FILE ...] [--csv FILE]

The values are the module's `multiscale_curvatures` with one layer (2
spacings): `a` is the automatic scale, which the layer reports.
"""
import argparse
import os
import sys

import numpy as np

import conformal_alpha_shapes as cas

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import cas3_benchmark  # noqa: E402


def changes(points, normals):
    """(name, points, normals, scaling) of each change."""
    diagonal = float(np.linalg.norm(points.max(axis=0) - points.min(axis=0)))
    turn = np.array([[0.0, -1.0, 0.0], [1.0, 0.0, 0.0], [0.0, 0.0, 1.0]])
    twice = np.random.default_rng(1).choice(len(points), len(points) // 20, replace=False)
    yield "translated 1e-7", points + 1e-7 * diagonal, normals, 1.0
    yield "translated 1e-4", points + 1e-4 * diagonal, normals, 1.0
    yield "scaled by 3", points * 3, normals, 3.0
    yield "turned 90 deg about z", points @ turn.T, None if normals is None else normals @ turn.T, 1.0
    yield "5% written twice", np.vstack([points, points[twice]]), \
        None if normals is None else np.vstack([normals, normals[twice]]), 1.0
    yield "reverse order", points[::-1], None if normals is None else normals[::-1], 1.0


def facts(points, normals):
    result = cas.multiscale_curvatures(points, normals, radii=("2s",))
    return result["r2s"].a, result.spacing, result.noise


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("inputs", nargs="+")
    parser.add_argument("--csv", help="also write the rows to this CSV file")
    args = parser.parse_args()
    rows = []
    for path in args.inputs:
        read = cas.read_point_cloud(path)
        points, normals = read if isinstance(read, tuple) else (read, None)
        a, spacing, noise = facts(points, normals)
        print(f"{os.path.basename(path)}: {len(points)} points, a {a:.6g}, spacing {spacing:.6g}, noise {noise:.4g}")
        for name, moved, moved_normals, scaling in changes(points, normals):
            a2, spacing2, noise2 = facts(moved, moved_normals)
            row = {"input": os.path.basename(path), "change": name,
                   "a_percent": 100 * (a2 / a - 1), "spacing_percent": 100 * (spacing2 / scaling / spacing - 1),
                   "noise_percent": 100 * (noise2 / noise - 1)}
            rows.append(row)
            print(f"  {name:24s} a {row['a_percent']:+.3f}%  spacing {row['spacing_percent']:+.3f}%  "
                  f"noise {row['noise_percent']:+.3f}%", flush=True)
    if args.csv:
        cas3_benchmark.write_csv(args.csv, ["input", "change", "a_percent", "spacing_percent", "noise_percent"], rows)


if __name__ == "__main__":
    main()
