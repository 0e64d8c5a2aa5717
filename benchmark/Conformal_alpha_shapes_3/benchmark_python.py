#!/usr/bin/python3
"""The Python module against the program, in one run, on the same points:
time and peak memory of `cas.multiscale_curvatures` (the call, and the call
plus `write_ply`) and of `conformal_curvature` (the whole job: read, compute,
write), each in a process of its own, alternating; the two curvatures.ply
compared byte for byte.

    PYTHONPATH=build/python /usr/bin/python3 benchmark/Conformal_alpha_shapes_3/benchmark_python.py \
        --program build/examples/Conformal_alpha_shapes_3/conformal_curvature --points 1000000 [--csv FILE]

The cloud is a noisy ellipsoid (noise 0.1 sample spacings along the normals),
written as .xyz and read by both through the program's reader. Both run with
the program's allocator policy, glibc.malloc.hugetlb=1 and one malloc arena
(the program sets them for itself; the Python process gets them from the
environment: GLIBC_TUNABLES and MALLOC_ARENA_MAX) unless --default-malloc.

With --interrupt T1,T2,...: instead, Ctrl-C latency: a call per T, SIGINT
sent T seconds after it starts, the time from the signal to the
KeyboardInterrupt printed.

--csv FILE writes a row per run, headed by the `# commit`, `# machine` and
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

from cas3_benchmark import write_csv

COLUMNS = ["run", "points", "program_wall_s", "program_cpu_s", "program_peak_mib", "call_wall_s", "call_cpu_s",
           "call_and_write_s", "module_peak_mib", "returned_mib", "same_bytes"]

CHILD = r"""
import json, resource, sys, time
import conformal_alpha_shapes as cas
points, normals = cas.read_point_cloud(sys.argv[1])
start, cpu = time.perf_counter(), time.process_time()
r = cas.multiscale_curvatures(points)
call, call_cpu = time.perf_counter() - start, time.process_time() - cpu
r.write_ply(sys.argv[2], precision="float32")  # the program's file, as the program writes it
total = time.perf_counter() - start
returned = sum(r[n][k].nbytes for n in r.layers for k in r[n].keys()) + r.outlier.nbytes
print(json.dumps({"call": call, "call_cpu": call_cpu, "call_and_write": total,
                  "peak_mib": resource.getrusage(resource.RUSAGE_SELF).ru_maxrss / 1024,
                  "returned_mib": returned / 2**20}))
"""


INTERRUPT_CHILD = r"""
import os, signal, sys, threading, time
import conformal_alpha_shapes as cas
points, normals = cas.read_point_cloud(sys.argv[1])
stages = []
for delay in map(float, sys.argv[2].split(",")):
    sent = []
    timer = threading.Timer(delay, lambda: (sent.append(time.perf_counter()), os.kill(os.getpid(), signal.SIGINT)))
    timer.start()
    try:
        cas.multiscale_curvatures(points, progress=lambda stage, f: stages.append(stage))
    except KeyboardInterrupt:
        stopped = time.perf_counter()
        print(f"SIGINT at {delay:6.1f} s (during '{stages[-1]}'): KeyboardInterrupt {stopped - sent[0]:.3f} s later",
              flush=True)
    timer.join()
    stages = []
"""


def ellipsoid(n, noise_in_spacings, seed=1):
    i = np.arange(n) + 0.5
    z = 1 - 2 * i / n
    r = np.sqrt(1 - z * z)
    phi = np.pi * (1 + 5 ** 0.5) * i
    unit = np.column_stack([r * np.cos(phi), r * np.sin(phi), z])
    axes = np.array([1.5, 1.0, 0.75])
    points = unit * axes
    normals = points / axes**2
    normals /= np.linalg.norm(normals, axis=1)[:, None]
    spacing = np.sqrt(4 * np.pi * 1.06**2 / n)  # about the surface's area over n
    return points + normals * np.random.default_rng(seed).normal(0, noise_in_spacings * spacing, n)[:, None]


def run_program(program, source, folder, env):
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    start = time.perf_counter()
    subprocess.run([program, source, "--quiet", "--output", folder], check=True, env=env)
    wall = time.perf_counter() - start
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return {"total": wall, "cpu": after.ru_utime + after.ru_stime - before.ru_utime - before.ru_stime,
            "peak_mib": after.ru_maxrss / 1024}


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--program", required=True)
    parser.add_argument("--points", type=int, default=1000000)
    parser.add_argument("--noise", type=float, default=0.1, help="in sample spacings")
    parser.add_argument("--repeat", type=int, default=1)
    parser.add_argument("--default-malloc", action="store_true")
    parser.add_argument("--interrupt", help="comma list of seconds after the start of a call to send SIGINT")
    parser.add_argument("--csv", help="where to write the runs as CSV")
    args = parser.parse_args()
    env = dict(os.environ)
    if not args.default_malloc:
        env["GLIBC_TUNABLES"] = "glibc.malloc.hugetlb=1"
        env["MALLOC_ARENA_MAX"] = "1"
    with tempfile.TemporaryDirectory() as folder:
        source = os.path.join(folder, "cloud.xyz")
        np.savetxt(source, ellipsoid(args.points, args.noise), fmt="%.17g")
        if args.interrupt:
            subprocess.run([sys.executable, "-c", INTERRUPT_CHILD, source, args.interrupt], check=True, env=env)
            return
        rows = []
        for k in range(args.repeat):
            program = run_program(args.program, source, os.path.join(folder, "program"), env)
            child = subprocess.run([sys.executable, "-c", CHILD, source, os.path.join(folder, "module.ply")],
                                   check=True, env=env, capture_output=True, text=True)
            module = json.loads(child.stdout)
            with open(os.path.join(folder, "program", "curvatures.ply"), "rb") as a, \
                 open(os.path.join(folder, "module.ply"), "rb") as b:
                same = a.read() == b.read()
            rows.append((program, module, same))
            print(f"run {k + 1}: program {program['total']:.1f} s wall, {program['cpu']:.1f} s CPU, "
                  f"peak {program['peak_mib']:.0f} MiB | python call {module['call']:.1f} s wall, "
                  f"{module['call_cpu']:.1f} s CPU, call + write_ply {module['call_and_write']:.1f} s, "
                  f"peak {module['peak_mib']:.0f} MiB (returned arrays {module['returned_mib']:.0f} MiB) | "
                  f"same curvatures.ply bytes: {same}")
        if args.csv:
            write_csv(args.csv, COLUMNS, [
                [k + 1, args.points, "%.3f" % p["total"], "%.3f" % p["cpu"], "%.1f" % p["peak_mib"],
                 "%.3f" % m["call"], "%.3f" % m["call_cpu"], "%.3f" % m["call_and_write"], "%.1f" % m["peak_mib"],
                 "%.1f" % m["returned_mib"], int(same)] for k, (p, m, same) in enumerate(rows)])
        program, module, same = rows[-1]
        print(f"ratios (last run): call / program job {module['call'] / program['total']:.3f}, "
              f"(call + write_ply) / program job {module['call_and_write'] / program['total']:.3f}, "
              f"call CPU / program CPU {module['call_cpu'] / program['cpu']:.3f}, "
              f"peak / (program peak + returned arrays) "
              f"{module['peak_mib'] / (program['peak_mib'] + module['returned_mib']):.3f}")
        if not all(r[2] for r in rows):
            sys.exit("the module's curvatures.ply differs from the program's")


if __name__ == "__main__":
    main()
