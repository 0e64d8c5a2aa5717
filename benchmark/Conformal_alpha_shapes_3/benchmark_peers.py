#!/usr/bin/python3
"""This package's default job against the tools users pick for the curvature
of a point cloud, in one run on the same noisy ellipsoid with its analytic
truth: wall and processor time, peak memory, the median relative error of
the mean curvature and the share of normals on the outward side.

    benchmark_peers.py --pipeline build/benchmark/Conformal_alpha_shapes_3/benchmark_pipeline \\
        --program build/examples/Conformal_alpha_shapes_3/conformal_curvature \\
        [--points 1000000] [--radii 4,8,16] [--cloudcompare CloudCompare] [--folder DIR] --csv FILE

benchmark_pipeline draws the ellipsoid 1 : 0.7 : 0.4 with Gaussian noise of
0.1 spacings along the normal (its "noisy" input), writes it as .xyz with
its truth (--write-points) and measures, each in a process of its own, the
Delaunay build (the unit of the other tables), CGAL jet fitting with 120
neighbors (serial, in the benchmark's process: no file read) and the
program `conformal_curvature` on the .xyz file (the whole default job,
reading and writing included). Then CloudCompare (Debian's `cloudcompare`,
run headless) reads the same .xyz, computes normals by octree at a radius,
orients them by a minimum spanning tree (its generic orientation) and the
mean curvature by its local quadric at the same radius, and writes ASCII;
one process per radius, given in sample spacings, its time and memory from
wait4. The error is median | |H| - |H_true| | / median |H_true| over all
points (the sign left out: jet fitting's and CloudCompare's follow no
orientation); for the program, its first layer (the automatic
neighborhood, the default), and its best of the five in the note. The
orientation is the share of normals whose dot product with the true
normal is positive, and the share of the majority side (a consistent
orientation up to one global sign). The CSV is headed by `# commit`,
`# machine` and `# command` (cas3_benchmark.py).
"""
import argparse
import csv
import os
import subprocess
import sys
import tempfile
import time

import numpy as np

from cas3_benchmark import write_csv

COLUMNS = ["tool", "setting", "n", "wall_s", "cpu_s", "peak_mib", "wall_x_delaunay", "median_relative_H_error",
           "outward_share", "majority_side_share", "note"]


def read_pipeline_csv(path):
    rows = [line for line in open(path) if not line.startswith("# ")]
    return list(csv.DictReader(rows))


def read_binary_ply(path):
    """The vertex element of a binary little-endian PLY file as a structured array."""
    types = {"double": "<f8", "float": "<f4", "uchar": "u1", "uint": "<u4", "int": "<i4"}
    with open(path, "rb") as f:
        head = f.read(1 << 20)
    end = head.index(b"end_header\n") + len(b"end_header\n")
    fields, count = [], None
    for line in head[:end].decode().splitlines():
        words = line.split()
        if words[:2] == ["element", "vertex"]:
            count = int(words[2])
        elif words[:1] == ["element"] and count is not None:
            break
        elif words[:1] == ["property"] and count is not None:
            fields.append((words[2], types[words[1]]))
    return np.fromfile(path, dtype=np.dtype(fields), count=count, offset=end)


def h_error(H, truth):
    """median | |H| - |H_true| | / median |H_true| over all points (NaN counts as an error of 100%)."""
    difference = np.abs(np.abs(H) - np.abs(truth))
    difference[~np.isfinite(difference)] = np.abs(truth[~np.isfinite(difference)])
    return float(np.median(difference) / np.median(np.abs(truth)))


def orientation(normals, truth_normals):
    outward = float(np.mean(np.einsum("ij,ij->i", normals, truth_normals) > 0))
    return outward, max(outward, 1 - outward)


def timed(command, env=None):
    """Runs `command`; its wall time, processor time and peak resident memory (MiB)."""
    start = time.perf_counter()
    child = subprocess.Popen(command, stdout=subprocess.DEVNULL, stderr=subprocess.PIPE, env=env)
    _, status, usage = os.wait4(child.pid, 0)
    wall = time.perf_counter() - start
    child.returncode = os.waitstatus_to_exitcode(status)
    error = child.stderr.read().decode(errors="replace")
    child.stderr.close()
    if child.returncode != 0:
        sys.exit("%s failed (exit %d): %s" % (" ".join(command), child.returncode, error[-2000:]))
    return wall, usage.ru_utime + usage.ru_stime, usage.ru_maxrss / 1024


def cloudcompare(executable, xyz, radius, output):
    command = [executable, "-SILENT", "-AUTO_SAVE", "OFF", "-C_EXPORT_FMT", "ASC", "-ADD_HEADER", "-O", xyz,
               "-OCTREE_NORMALS", repr(radius), "-ORIENT_NORMS_MST", "6", "-CURV", "MEAN", repr(radius),
               "-SAVE_CLOUDS", "FILE", output]
    measured = timed(command, env=dict(os.environ, QT_QPA_PLATFORM="offscreen"))
    if not os.path.exists(output):
        sys.exit("%s wrote no %s" % (" ".join(command), output))
    with open(output) as f:
        names = f.readline().lstrip("/").split()
    values = np.loadtxt(output, comments="/")
    column = {name: k for k, name in enumerate(names)}
    curvature = next(k for name, k in column.items() if name.startswith("Mean_curvature"))
    return measured, values[:, :3], values[:, curvature], values[:, [column["Nx"], column["Ny"], column["Nz"]]]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--pipeline", required=True, help="the benchmark_pipeline binary")
    parser.add_argument("--program", required=True, help="the conformal_curvature binary")
    parser.add_argument("--cloudcompare", default="CloudCompare")
    parser.add_argument("--points", type=int, default=1000000)
    parser.add_argument("--radii", default="4,8,16", help="CloudCompare's radii in sample spacings")
    parser.add_argument("--folder", help="where the clouds and outputs go (default: a temporary folder)")
    parser.add_argument("--csv", required=True)
    args = parser.parse_args()
    folder = args.folder or tempfile.mkdtemp(prefix="benchmark_peers_")
    os.makedirs(folder, exist_ok=True)
    pipeline_csv = os.path.join(folder, "pipeline.csv")
    subprocess.run([args.pipeline, "--sizes", str(args.points), "--surfaces", "noisy", "--no-bunny",
                    "--no-pipeline", "--no-parts", "--program", os.path.abspath(args.program),
                    "--write-points", folder, "--tmp", folder, "--csv", pipeline_csv], check=True)
    stem = os.path.join(folder, "ellipsoid_noisy_%d" % args.points)
    with open(stem + "_truth.txt") as f:
        spacing = float(f.readline().split()[2])
    truth = np.loadtxt(stem + "_truth.txt", comments="#")
    H_true, n_true = truth[:, 0], truth[:, 1:4]
    points = np.loadtxt(stem + ".xyz")
    measured = {r["process"]: r for r in read_pipeline_csv(pipeline_csv) if r["group"] != "failure"}
    for process in ("delaunay", "jet", "program"):
        if process not in measured:
            sys.exit("benchmark_pipeline measured no %s: see %s" % (process, pipeline_csv))
    delaunay = float(measured["delaunay"]["wall_s"])
    rows = [{"tool": "CGAL Delaunay_triangulation_3 (the unit; memory: what it adds to the points)", "setting": "",
             "n": args.points,
             "wall_s": "%.2f" % delaunay, "cpu_s": "%.2f" % float(measured["delaunay"]["cpu_s"]),
             "peak_mib": "%.0f" % float(measured["delaunay"]["peak_added_mib"]), "wall_x_delaunay": "1.00",
             "note": "in the benchmark's process; peak: added to the points"}]

    def row(tool, setting, wall, cpu, peak, error, oriented=("", ""), note=""):
        rows.append({"tool": tool, "setting": setting, "n": args.points, "wall_s": "%.2f" % wall, "cpu_s": "%.2f" % cpu,
                     "peak_mib": "%.0f" % peak, "wall_x_delaunay": "%.2f" % (wall / delaunay),
                     "median_relative_H_error": "%.4f" % error,
                     "outward_share": oriented[0] if oriented[0] == "" else "%.4f" % oriented[0],
                     "majority_side_share": oriented[1] if oriented[1] == "" else "%.4f" % oriented[1],
                     "note": note})
        print("%-40s %-28s %8s s %8s MiB  H error %s" % (tool, setting, rows[-1]["wall_s"], rows[-1]["peak_mib"],
                                                         rows[-1]["median_relative_H_error"]))

    cloud = read_binary_ply(os.path.join(stem + "_program", "curvatures.ply"))
    labels = [name[2:] for name in cloud.dtype.names if name.startswith("H_") and not name.startswith("H_sigma")]
    errors = {label: h_error(cloud["H_" + label].astype(np.float64), H_true) for label in labels}
    best = min(errors, key=errors.get)
    normals = np.column_stack([cloud["n%s_%s" % (axis, labels[0])] for axis in "xyz"]).astype(np.float64)
    program = measured["program"]
    row("this package: conformal_curvature", "default job, layer " + labels[0], float(program["wall_s"]),
        float(program["cpu_s"]), float(program["peak_process_mib"]), errors[labels[0]], orientation(normals, n_true),
        "whole process, .xyz read and two binary PLY written; best layer %s: %.4f" % (best, errors[best]))
    jet_H = np.loadtxt(stem + "_jet_H.txt")
    jet = measured["jet"]
    row("CGAL Monge_via_jet_fitting", "degree 2, 120 neighbors, serial", float(jet["wall_s"]), float(jet["cpu_s"]),
        float(jet["peak_process_mib"]), h_error(jet_H, H_true),
        note="in the benchmark's process (the points in memory, no file read); no oriented normal")
    best_cc = None
    for radius in [float(r) for r in args.radii.split(",")]:
        output = stem + "_cloudcompare_%gs.asc" % radius
        (wall, cpu, peak), xyz, H, cc_normals = cloudcompare(args.cloudcompare, stem + ".xyz", radius * spacing, output)
        if xyz.shape != points.shape or np.max(np.abs(xyz - points)) > 1e-6 * np.ptp(points):
            sys.exit("CloudCompare's %s does not hold the input's points in the input's order" % output)
        error = h_error(H, H_true)
        row("CloudCompare", "radius %g spacings" % radius, wall, cpu, peak, error, orientation(cc_normals, n_true),
            "-OCTREE_NORMALS r -ORIENT_NORMS_MST 6 -CURV MEAN r; whole process, .xyz read and ASCII written")
        if best_cc is None or error < best_cc[0]:
            best_cc = (error, len(rows) - 1)
    rows[best_cc[1]]["note"] += "; the best radius"
    write_csv(args.csv, COLUMNS, rows)
    print("written: %s (spacing %.6g; clouds and outputs in %s)" % (args.csv, spacing, folder))


if __name__ == "__main__":
    main()
