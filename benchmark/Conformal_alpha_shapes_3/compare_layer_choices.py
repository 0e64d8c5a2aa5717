#!/usr/bin/python3
"""Ways of taking one value per point from the default job's layers, scored
against the analytic truth: the automatic layer (its own choice of radius
per point), each fixed layer, the fixed layer of least H_sigma per point,
and the fixed layers' mean weighted by 1 / H_sigma^2. Prints a row per
sample: the median relative error of H, in percent, of each (the manual,
"Uncertainty").

    build/benchmark/Conformal_alpha_shapes_3/evaluate_surfaces --case ellipsoid,torus,bumpy_sphere,ellipsoid_cap \\
        --sizes 100000 --noise 0,0.1,0.3 --no-jet --write-points DIR
    PYTHONPATH=build/python /usr/bin/python3 benchmark/Conformal_alpha_shapes_3/compare_layer_choices.py DIR \\
        [--csv FILE]

Reads each DIR/NAME_N_NOISE.xyz and its DIR/NAME_N_NOISE_truth.txt (the
true normal, H and K per point); the signs of H follow each point's
automatic normal against the true one, which holds for open samples too.
"""
import argparse
import glob
import os
import sys

import numpy as np

import conformal_alpha_shapes as cas

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import cas3_benchmark  # noqa: E402

FIXED = ("r2s", "r4s", "r8s", "r16s")


def choices(result):
    """Each way's H per point, by name."""
    H = np.stack([np.asarray(result[name].H) for name in FIXED], axis=1)
    sigma = np.stack([np.asarray(result[name].H_sigma) for name in FIXED], axis=1)
    sigma = np.where(np.isfinite(sigma) & np.isfinite(H), sigma, np.inf)
    rows = np.arange(len(H))
    weights = 1 / sigma ** 2
    with np.errstate(invalid="ignore", divide="ignore"):
        mean = np.sum(np.where(np.isfinite(H), H, 0) * weights, axis=1) / np.sum(weights, axis=1)
    out = {"auto": np.asarray(result["rauto"].H)}
    out.update({name: H[:, k] for k, name in enumerate(FIXED)})
    out["least sigma"] = H[rows, np.argmin(sigma, axis=1)]
    out["1/sigma^2 mean"] = mean
    return out


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("folder", help="what evaluate_surfaces --write-points wrote")
    parser.add_argument("--csv", help="also write the rows to this CSV file")
    args = parser.parse_args()
    samples = sorted(p for p in glob.glob(os.path.join(args.folder, "*.xyz")))
    if not samples:
        sys.exit(f"compare_layer_choices: no .xyz sample in {args.folder}")
    rows = []
    for path in samples:
        truth_path = path[:-len(".xyz")] + "_truth.txt"
        if not os.path.exists(truth_path):
            sys.exit(f"compare_layer_choices: {truth_path} is missing (evaluate_surfaces --write-points writes it)")
        points = np.loadtxt(path)
        truth = np.loadtxt(truth_path)
        normal, H_true = truth[:, :3], truth[:, 3]
        result = cas.multiscale_curvatures(points)
        side = np.sign(np.sum(np.asarray(result["rauto"].normal) * normal, axis=1))
        row = {"sample": os.path.basename(path)[:-len(".xyz")]}
        for name, H in choices(result).items():
            with np.errstate(invalid="ignore"):
                error = np.abs(side * H - H_true) / np.abs(H_true)
            row[name] = 100 * float(np.nanmedian(error))
        rows.append(row)
        print(row["sample"].ljust(30) + "  ".join(f"{k} {v:.2f}%" for k, v in row.items() if k != "sample"),
              flush=True)
    if args.csv:
        cas3_benchmark.write_csv(args.csv, list(rows[0]), rows)


if __name__ == "__main__":
    main()
