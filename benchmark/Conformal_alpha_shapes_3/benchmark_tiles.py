#!/usr/bin/python3
"""A tiled run on Dask against one run, on the same noisy scene: the answer
(spacing, noise, the automatic scale, outliers, normal signs and the median
relative difference of H per layer, every index once), wall and processor
time, and peak memory (one run's process; each worker's).

    PYTHONPATH=build/python /usr/bin/python3 benchmark/Conformal_alpha_shapes_3/benchmark_tiles.py \
        --points 1000000 --tile-points 250000 --workers 2 [--csv FILE]

The scene is the tests' (python/tests/test_tiles.py): a closed ellipsoid
above an open wavy sheet, Gaussian noise of 0.1 spacings, 5 far outliers.
One run is ``multiscale_curvatures`` in a process of its own with TBB on
every core (the program's values to the last bit); the tiled run is
``python3 -m conformal_alpha_shapes.tiles`` with an embedded LocalCluster.
With --no-one-run only the tiled run (clouds one process cannot hold);
with --input FILE a scan instead of the scene (with its normals, if any);
--halo SPACINGS is the tiled run's (default: its own).
With --a-spread, one run's own automatic scale on the cloud translated by
1e-10, 1e-7 and 1e-4 of its bounding box's diagonal (far below its
spacing): a translation changes no distance beyond rounding, but it changes
every point's coordinate hash, so the points that sample the spacing and
the noise, so the denoising and the front; the tiled run's difference in
`a` is read against that spread. With --las instead, the scene's points at 1e-7
steps as LAS 1.4 (point format 6, an extra-bytes field, a WKT CRS) and as
binary PLY, a tiled run on each (--merge, --las for the LAS): each driver's
peak memory (its own, not its workers': the peak RSS, and the anonymous
memory sampled every 50 ms), and whether the merged files hold
the same values and the LAS the input's records and extra bytes.
The result is printed as JSON; --csv FILE also writes it as `quantity,value`
rows (nested keys joined by dots) headed by the `# commit`, `# machine` and
`# command` lines (cas3_benchmark.py).
"""
import argparse
import json
import os
import resource
import subprocess
import sys
import tempfile
import time

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python", "tests"))
from test_tiles import scene  # noqa: E402
from cas3_benchmark import write_csv  # noqa: E402

# The peaks of one run's process and of the driver are their VmHWM:
# ru_maxrss also counts what this process held when it forked them.
ONE_RUN = r"""
import json, sys, time
import numpy as np
import conformal_alpha_shapes as cas
cloud = np.load(sys.argv[1])
points, normals = cloud[:, :3], (cloud[:, 3:] if cloud.shape[1] == 6 else None)
start, cpu = time.perf_counter(), time.process_time()
r = cas.multiscale_curvatures(points, normals)
wall, cpu = time.perf_counter() - start, time.process_time() - cpu
np.savez(sys.argv[2], outlier=r.outlier, **{f"n_{k}": r[k].normal.astype(np.float32) for k in r.layers},
         **{f"H_{k}": r[k].H for k in r.layers})
print(json.dumps({"wall": wall, "cpu": cpu, "a": r[r.layers[0]].a, "spacing": r.spacing, "noise": r.noise,
                  "layers": list(r.layers),
                  "peak": int(next(line for line in open("/proc/self/status")
                                   if line.startswith("VmHWM:")).split()[1]) * 1024}))
"""


def compare(folder, one, reference):
    """The tiled run's merged file against one run's arrays."""
    from conformal_alpha_shapes import tile_io
    manifest = tile_io.read_manifest(os.path.join(folder, "manifest.json"))
    names = manifest["names"]
    path = os.path.join(folder, "curvatures.ply")
    with open(path, "rb") as f:
        head = f.read(1 << 16)
    merged = np.memmap(path, dtype=tile_io.part_dtype(names, False), mode="r",
                       offset=head.index(b"end_header\n") + len(b"end_header\n"))
    indices = np.concatenate([tile_io.read_part(os.path.join(folder, "parts", f"part_{t:05d}.ply"),
                                                names)["input_index"] for t in range(manifest["tiles"])])
    out = {"every_index_once": bool(np.array_equal(np.sort(indices.astype(np.int64)), np.arange(len(merged)))),
           "outliers_equal": bool(np.array_equal(merged["outlier"].astype(bool), reference["outlier"])),
           "spacing_relative": manifest["spacing"] / one["spacing"] - 1,
           "noise_relative": manifest["noise"] / one["noise"] - 1,
           "a_relative": manifest["a"] / one["a"] - 1, "layers": {}}
    for name in names:
        normal = np.column_stack([merged[f"n{axis}_{name}"] for axis in "xyz"]).astype(np.float64)
        dot = np.einsum("ij,ij->i", normal, reference[f"n_{name}"].astype(np.float64))
        valid = np.isfinite(dot)
        H, H_one = merged[f"H_{name}"].astype(np.float64), reference[f"H_{name}"]
        both = np.isfinite(H) & np.isfinite(H_one)
        out["layers"][name] = {
            "same_normal_sign": float(np.mean(dot[valid] > 0)),
            "median_relative_H_difference": float(np.median(np.abs(H[both] - H_one[both]))
                                                  / np.median(np.abs(H_one[both])))}
    return out


DRIVER = r"""
import runpy, sys
sys.argv = ["conformal_alpha_shapes.tiles"] + sys.argv[1:]
try:
    runpy.run_module("conformal_alpha_shapes.tiles", run_name="__main__")
finally:
    print(int(next(line for line in open("/proc/self/status") if line.startswith("VmHWM:")).split()[1]) * 1024,
          file=sys.stderr)
"""


def las_against_ply(cloud, folder, args):
    """Tiled runs on the same points as LAS and as PLY: drivers' peak memory, same answer."""
    import las_spec
    from conformal_alpha_shapes import tile_io
    points = np.load(cloud, mmap_mode="r")[:, :3]
    step = 1e-7
    integers = np.round(np.asarray(points) / step).astype(np.int32)
    fields = las_spec.sample_fields(len(points), 6)
    for k, axis in enumerate("XYZ"):
        fields[axis] = integers[:, k]
    reflectance = np.arange(len(points), dtype=np.float32)
    paths = {"las": os.path.join(folder, "scene.las"), "ply": os.path.join(folder, "scene.ply")}
    las_spec.write_las(paths["las"], 4, 6, fields, scale=(step,) * 3, offset=(0.0,) * 3, crs="wkt",
                       extra=[("reflectance", "<f4", reflectance)])
    with open(paths["ply"], "wb") as f:
        f.write(f"ply\nformat binary_little_endian 1.0\nelement vertex {len(points)}\nproperty double x\n"
                "property double y\nproperty double z\nend_header\n".encode())
        (integers.astype(np.float64) * step).tofile(f)
    del integers, fields, reflectance
    out = {}
    for kind, path in paths.items():
        start = time.perf_counter()
        log = open(os.path.join(folder, f"tiled_{kind}.log"), "w+")
        run = subprocess.Popen([sys.executable, "-c", DRIVER, path, "--output", os.path.join(folder, f"tiled_{kind}"),
                                "--tile-points", str(args.tile_points), "--workers", str(args.workers), "--merge",
                                "--quiet"] + (["--las"] if kind == "las" else []), stderr=log)
        # the peak RSS counts the pages of the memory-mapped files it writes
        # (the merged file), which the kernel may drop: the anonymous memory
        # (RssAnon) is sampled too
        anonymous = 0
        while run.poll() is None:
            try:
                with open(f"/proc/{run.pid}/status") as f:
                    anonymous = max([anonymous] + [int(line.split()[1]) * 1024 for line in f
                                                   if line.startswith("RssAnon:")])
            except OSError:
                pass
            time.sleep(0.05)
        log.seek(0)
        stderr = log.read()
        log.close()
        if run.returncode:
            raise RuntimeError(f"the tiled run on {path} failed: {stderr}")
        out[kind] = {"wall": time.perf_counter() - start, "driver_peak_rss": int(stderr.split()[-1]),
                     "driver_peak_anonymous_sampled": anonymous, "input_bytes": os.path.getsize(path)}
    names = tile_io.read_manifest(os.path.join(folder, "tiled_ply", "manifest.json"))["names"]
    merged_path = os.path.join(folder, "tiled_ply", "curvatures.ply")
    merged = np.memmap(merged_path, dtype=tile_io.part_dtype(names, False), mode="r",
                       offset=len(tile_io.part_header(merged_path)))
    header, records, extra, xyz = las_spec.read_las(os.path.join(folder, "tiled_las", "curvatures.las"))
    same = all(np.array_equal(extra[f"{value}_{name}"], merged[f"{value}_{name}"], equal_nan=True)
               for name in names for value in ("nx", "ny", "nz", "H", "K", "k1", "k2", "radius", "distance"))
    input_header, input_records, input_extra, _ = las_spec.read_las(paths["las"])
    out["same_values"] = bool(same and np.array_equal(extra["outlier"], merged["outlier"]))
    out["same_points"] = bool(np.array_equal(xyz[:, 0], merged["x"]) and np.array_equal(xyz[:, 2], merged["z"]))
    out["input_records_kept"] = bool(np.array_equal(records["X"], input_records["X"])
                                     and np.array_equal(records["gps_time"], input_records["gps_time"])
                                     and np.array_equal(extra["reflectance"], input_extra["reflectance"])
                                     and las_spec.crs_records(header) == las_spec.crs_records(input_header))
    return out


def a_spread(cloud):
    """One run's automatic scale on the cloud translated by small fractions
    of its diagonal, relative to the untranslated cloud's."""
    import conformal_alpha_shapes as cas
    data = np.load(cloud)
    points, normals = data[:, :3], (data[:, 3:] if data.shape[1] == 6 else None)
    diagonal = float(np.linalg.norm(points.max(axis=0) - points.min(axis=0)))

    def a(shift):
        result = cas.multiscale_curvatures(points + shift * diagonal, normals, radii=["2s"])
        return result[result.layers[0]].a

    reference = a(0.0)
    return {f"{shift:g}": a(shift) / reference - 1 for shift in (1e-10, 1e-7, 1e-4)}


def flatten(value, prefix=""):
    """[dotted key, value] for every leaf of a nested dict."""
    if not isinstance(value, dict):
        return [[prefix, value]]
    return [row for key, item in value.items() for row in flatten(item, f"{prefix}.{key}" if prefix else str(key))]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--points", type=int, default=1_000_000)
    parser.add_argument("--tile-points", type=int, default=250_000)
    parser.add_argument("--workers", type=int, default=2)
    parser.add_argument("--input", default=None,
                        help="a cloud the program reads (.xyz, .ply, ...) instead of the scene, with its normals")
    parser.add_argument("--folder", default=None, help="where the cloud and the outputs go (default: a temporary one)")
    parser.add_argument("--no-one-run", action="store_true")
    parser.add_argument("--halo", help="the tiled run's halo in spacings (default: its own)")
    parser.add_argument("--csv", help="where to write the result as quantity,value rows")
    parser.add_argument("--las", action="store_true",
                        help="also tiled runs on the points as LAS and as PLY: drivers' memory, same answer")
    parser.add_argument("--a-spread", action="store_true",
                        help="also one run's automatic scale on the cloud translated by tiny fractions of its size")
    args = parser.parse_args()
    folder = args.folder or tempfile.mkdtemp(prefix="benchmark_tiles_")
    os.makedirs(folder, exist_ok=True)
    cloud = os.path.join(folder, "scene.npy")
    if args.input:
        from conformal_alpha_shapes import read_point_cloud
        points, normals = read_point_cloud(args.input)
        np.save(cloud, points if normals is None else np.hstack([points, normals]))
    elif not os.path.exists(cloud):
        np.save(cloud, scene(args.points)[0])
    result = {"points": int(np.load(cloud, mmap_mode="r").shape[0]), "tile_points": args.tile_points,
              "workers": args.workers}
    if args.las:
        result["las_against_ply"] = las_against_ply(cloud, folder, args)
        print(json.dumps(result, indent=1))
        if args.csv:
            write_csv(args.csv, ["quantity", "value"], flatten(result))
        return
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    subprocess.run([sys.executable, "-m", "conformal_alpha_shapes.tiles", cloud, "--output",
                    os.path.join(folder, "tiled"), "--tile-points", str(args.tile_points), "--workers",
                    str(args.workers), "--merge"] + (["--halo", args.halo] if args.halo else []), check=True)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    with open(os.path.join(folder, "tiled", "summary.json")) as f:
        summary = json.load(f)
    result["tiled"] = {"wall": time.perf_counter() - start,
                       "cpu": (after.ru_utime + after.ru_stime) - (before.ru_utime + before.ru_stime),
                       "worker_peak_memory": summary["worker_peak_memory"], "tiles": summary["tiles"],
                       "points_with_halos": summary["tile_points_with_halo"],
                       "worst_tile": summary["worst_tile"], "worst_seam_agreement": summary["worst_seam_agreement"],
                       "storage": sum(os.path.getsize(os.path.join(root, name))
                                      for root, _, names in os.walk(os.path.join(folder, "tiled"))
                                      for name in names)}
    if not args.no_one_run:
        before = resource.getrusage(resource.RUSAGE_CHILDREN)
        # the program's allocator policy, as the tiles' workers have it
        from conformal_alpha_shapes.tiles import WORKER_MALLOC_POLICY
        run = subprocess.run([sys.executable, "-c", ONE_RUN, cloud, os.path.join(folder, "one.npz")],
                             check=True, capture_output=True, text=True, env=dict(os.environ, **WORKER_MALLOC_POLICY))
        after = resource.getrusage(resource.RUSAGE_CHILDREN)
        one = json.loads(run.stdout)
        one["process_cpu"] = (after.ru_utime + after.ru_stime) - (before.ru_utime + before.ru_stime)
        result["one_run"] = one
        result["answer"] = compare(os.path.join(folder, "tiled"), one, np.load(os.path.join(folder, "one.npz")))
    if args.a_spread:
        result["one_run_a_spread"] = a_spread(cloud)
    print(json.dumps(result, indent=1))
    if args.csv:
        write_csv(args.csv, ["quantity", "value"], flatten(result))


if __name__ == "__main__":
    main()
