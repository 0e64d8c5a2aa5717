#!/usr/bin/python3
"""Benchmark of surface region matching: multi-scale curvature descriptors against Open3D's FPFH.

For each pair of protein chains (1HPV chains A and B, 1TII chains D and E,
from Debian's pymol-data), each chain's molecular surface is sampled alone
(molecular_surface_points --chains, spacing 0.4 A, with normals) and its
curvature computed at radii 1.5, 3, 6, 9 and 12 A (conformal_curvature).
Then 300 farthest-point centres on the first chain are each ranked against
a 2,000-point farthest-point sample of the second; a hit is a candidate
within 3 A of the centre's true place, found by superposing the CA atoms of
the two chains (which the matcher never sees). Both methods see the same
centres, candidates and rings (0-2, 2-4, ... 12-14 A):
  - curvature: region_descriptors (shape index and curvedness histograms
    per ring and radius, and histograms of the normals' cosines and the
    heights over the centre's tangent plane, the r3 layer's normal),
    histogram_distances (earth mover's, rings weighted by their radius);
    top-1 / top-10 as ranked by the descriptors, then after match_regions'
    re-ranking of each centre's 50 best by the registration from the matches;
  - FPFH as usually used (one radius, 10 A), and FPFH in the same rings
    (FPFH at radius 3 A averaged over each ring's points, per ring),
    chi-square distances.
The buried pairs (hpv-buried, tii-buried) match a chain seen inside its
complex against the same chain alone: the complex of the two chains is
sampled, then only the points nearest (surface distance) to the first
chain's atoms are kept, so its interface is missing and the surface next
to it is the complex's; both methods' features (curvature, FPFH) are
computed on those points, as they are on the chain alone's. Also: the registration of the second chain onto
the first from the matches (CA RMSD), a rotated, translated copy of the
first chain matched against itself (invariance), and the times (wall):
the descriptors and matching of the pair, and the curvature of the two
surfaces (conformal_curvature, run again right after, for the time only).
Last, the time at a given size (--timing-points, 20,000 by default): 1HPV
chains A and B sampled at 0.35 A, each cut to its first N farthest points,
their curvature at the five radii (conformal_curvature) against their
descriptors and matching (the same 300 centres and 2,000 candidates).

The results go to the standard output and to a CSV file (--csv) headed by
the lines "# commit", "# machine" and "# command", as the C++ benchmarks'.

Usage:
  benchmark_matching.py --build BUILD_DIR [--work DIR] [--csv FILE] [--pairs hpv,tii,hpv-buried,tii-buried]
                        [--no-fpfh] [--timing-points N]
BUILD_DIR holds examples/Conformal_alpha_shapes_3/{molecular_surface_points,conformal_curvature}
and python/ (the module, whose matching is the C++ library's). Needs pymol-data; FPFH needs
python3-open3d.
"""

import argparse
import os
import platform
import subprocess
import sys
import time

import numpy as np

HPV, TII = "/usr/share/pymol/data/tut/1hpv.pdb", "/usr/share/pymol/data/demo/1tii.pdb"
# pdb, first chain, second chain, the complex the first chain is sampled in (None: alone)
PAIRS = {
    "hpv": (HPV, "A", "B", None),
    "tii": (TII, "D", "E", None),
    "hpv-buried": (HPV, "A", "A", "AB"),
    "tii-buried": (TII, "D", "D", "DE"),
}
BONDI = {"H": 1.2, "C": 1.7, "N": 1.55, "O": 1.52, "S": 1.8, "P": 1.8, "F": 1.47, "CL": 1.75, "BR": 1.85,
         "I": 1.98, "SE": 1.9}
WATERS = ("HOH", "WAT", "H2O", "DOD", "SOL")
RADII = (1.5, 3.0, 6.0, 9.0, 12.0)
RINGS = (2.0, 4.0, 6.0, 8.0, 10.0, 12.0, 14.0)
CENTRES, CANDIDATES, HIT = 300, 2000, 3.0
COLUMNS = ("pair", "method", "top1", "top10", "ca_rmsd", "consistent", "points_a", "points_b", "seconds")
SOURCE_DIR = os.path.normpath(os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", ".."))


def first_output_line(command):
    """The first line that `command` prints, or "unknown"."""
    try:
        lines = subprocess.run(command, capture_output=True, text=True, check=False).stdout.splitlines()
    except OSError:
        return "unknown"
    return lines[0] if lines and lines[0] else "unknown"


def proc_field(name, key):
    """The value of the first line of /proc/`name` that starts with `key`."""
    try:
        with open("/proc/" + name) as f:
            for line in f:
                if line.startswith(key):
                    return line[len(key):].lstrip(" \t:").rstrip("\n")
    except OSError:
        pass
    return "unknown"


def provenance():
    """The lines "# commit", "# machine" and "# command" that head the CSV file (those of
    benchmark/Conformal_alpha_shapes_3/include/cas3_benchmark.h)."""
    commit = first_output_line(["git", "-C", SOURCE_DIR, "describe", "--always", "--dirty", "--tags"])
    machine = (f"{proc_field('cpuinfo', 'model name')}, {os.cpu_count()} cores, {proc_field('meminfo', 'MemTotal')}"
               if platform.system() == "Linux" else "unknown")
    return f"# commit {commit}\n# machine {machine}\n# command {' '.join(sys.argv)}\n"


def write_csv(path, rows):
    """The rows (dicts of COLUMNS) as CSV under the provenance lines, written whole or not at all."""
    temporary = path + ".partial"
    with open(temporary, "w") as f:
        f.write(provenance())
        f.write(",".join(COLUMNS) + "\n")
        for row in rows:
            f.write(",".join(("%.4g" % row[c] if isinstance(row.get(c), float) else str(row.get(c, "")))
                             for c in COLUMNS) + "\n")
    os.replace(temporary, path)


def read_ply(path):
    """The vertex element of a binary little-endian PLY as a numpy structured array."""
    types = {"double": "<f8", "float": "<f4", "uchar": "u1", "int": "<i4", "uint": "<u4", "short": "<i2",
             "ushort": "<u2", "char": "i1"}
    with open(path, "rb") as f:
        fields, count = [], 0
        while True:
            line = f.readline().decode("ascii").strip()
            if line.startswith("element vertex"):
                count = int(line.split()[2])
            elif line.startswith("property"):
                _, kind, name = line.split()
                fields.append((name, types[kind]))
            elif line == "end_header":
                break
        return np.frombuffer(f.read(np.dtype(fields).itemsize * count), dtype=np.dtype(fields), count=count)


def layers_from_ply(values):
    """The curvature layers of the benchmark's radii, and the r3 layer's normals."""
    layers = []
    for r in RADII:
        suffix = ("r%g" % r).replace(".", "p")
        layers.append({"k1": values["k1_" + suffix].astype(np.float64), "k2": values["k2_" + suffix].astype(np.float64),
                       "radius": values["radius_" + suffix].astype(np.float64)})
    normals = np.column_stack([values["nx_r3"], values["ny_r3"], values["nz_r3"]]).astype(np.float64)
    return layers, normals


def ca_atoms(pdb, chain):
    atoms = {}
    for line in open(pdb):
        if line.startswith("ATOM") and line[12:16] == " CA " and line[21] == chain and line[16] in " A":
            atoms[line[22:27]] = [float(line[30:38]), float(line[38:46]), float(line[46:54])]
    return atoms


def common_ca_atoms(pdb, chain_a, chain_b):
    """The CA atoms of the residues numbered alike in both chains: two (N, 3) arrays, row by row the same
    residue, to superpose the chains by."""
    ca_a, ca_b = ca_atoms(pdb, chain_a), ca_atoms(pdb, chain_b)
    common = sorted(set(ca_a) & set(ca_b))
    return np.array([ca_a[k] for k in common]), np.array([ca_b[k] for k in common])


def atoms(pdb, chains):
    """Centres, radii and chains of the atoms molecular_surface_points keeps by default (no hydrogens,
    no waters, first alternate location), of the given chains."""
    xyz, radius, chain = [], [], []
    for line in open(pdb):
        if line.startswith("ENDMDL"):
            break
        if not line.startswith(("ATOM", "HETATM")) or line[21] not in chains or line[16] not in " A":
            continue
        element = (line[76:78].strip() or line[12:14].strip()).upper()
        if element in ("H", "D") or line[17:20].strip() in WATERS:
            continue
        xyz.append([float(line[30:38]), float(line[38:46]), float(line[46:54])])
        radius.append(BONDI.get(element, 2.0))
        chain.append(line[21])
    return np.array(xyz), np.array(radius), np.array(chain)


def curvature(build, xyz, output):
    """Runs conformal_curvature at the benchmark's radii; its wall time in seconds."""
    start = time.time()
    subprocess.run([os.path.join(build, "examples", "Conformal_alpha_shapes_3", "conformal_curvature"), xyz,
                    "--radius", ",".join("%g" % r for r in RADII), "--output", output, "--quiet"], check=True)
    return time.time() - start


def nearest_atoms(points, centres, k):
    """The indices of the k atom centres nearest to each point (numpy, by blocks of points)."""
    index = np.empty((len(points), k), dtype=np.int64)
    for start in range(0, len(points), 2048):
        block = points[start:start + 2048]
        squared = ((block[:, None, :] - centres[None, :, :]) ** 2).sum(axis=2)
        index[start:start + len(block)] = np.argpartition(squared, k - 1, axis=1)[:, :k]
    return index


def surface(build, work, pdb, chain, complex_chains=None, spacing=0.4):
    """Points, normals and curvature values (the PLY's vertex array) of one chain's surface: sampled
    alone, or sampled in a complex, then only the points nearest to the chain's atoms kept (and their
    curvature computed on those points alone). Cached in work."""
    tools = os.path.join(build, "examples", "Conformal_alpha_shapes_3")
    stem = os.path.join(work, os.path.basename(pdb)[:-4] + ("_" if spacing == 0.4 else "_%g_" % spacing))
    for chains in filter(None, (chain, complex_chains)):
        if not os.path.exists(stem + chains + ".xyz"):
            subprocess.run([os.path.join(tools, "molecular_surface_points"), pdb, stem + chains + ".xyz", "--chains",
                            chains, "--normals", "--spacing", "%g" % spacing, "--quiet"], check=True)
    base = stem + (f"{chain}_in_{complex_chains}" if complex_chains else chain)
    if complex_chains and not os.path.exists(base + ".xyz"):
        xyz = np.loadtxt(stem + complex_chains + ".xyz")
        centres, radii, owner = atoms(pdb, complex_chains)
        index = nearest_atoms(xyz[:, :3], centres, 8)
        gap = np.linalg.norm(xyz[:, None, :3] - centres[index], axis=2) - radii[index]  # to each atom's sphere
        mine = owner[index[np.arange(len(xyz)), np.argmin(gap, axis=1)]] == chain
        np.savetxt(base + ".xyz", xyz[mine], fmt="%.6f")
    ply = os.path.join(base + "_curvature", "curvatures.ply")
    if not os.path.exists(ply):
        curvature(build, base + ".xyz", base + "_curvature")
    xyz = np.loadtxt(base + ".xyz")
    return xyz[:, :3], xyz[:, 3:6], read_ply(ply), base + ".xyz"


def fpfh(points, normals, radius):
    import open3d as o3d
    cloud = o3d.geometry.PointCloud(o3d.utility.Vector3dVector(points))
    cloud.normals = o3d.utility.Vector3dVector(normals)
    feature = o3d.pipelines.registration.compute_fpfh_feature(
        cloud, o3d.geometry.KDTreeSearchParamHybrid(radius=radius, max_nn=1000))
    return np.asarray(feature.data).T / 100.0  # each of the 3 histograms sums to 100


def ring_average(points, features, centres, rings):
    """Per centre, the mean feature of the points in each ring, concatenated."""
    out = np.zeros((len(centres), len(rings) * features.shape[1]))
    for row, c in enumerate(centres):
        d = np.linalg.norm(points - points[c], axis=1)
        inner = 0.0
        for k, outer in enumerate(rings):
            mask = (d >= inner) & (d <= outer) if k else d <= outer
            if mask.any():
                out[row, k * features.shape[1]:(k + 1) * features.shape[1]] = features[mask].mean(axis=0)
            inner = outer
    return out


def rates(distances, true_places, candidate_points):
    """top-1 and top-10 hit rates of a (centres, candidates) distance matrix."""
    order = np.argsort(distances, axis=1, kind="stable")[:, :10]
    miss = np.linalg.norm(candidate_points[order] - true_places[:, None, :], axis=2)
    return float(np.mean(miss[:, 0] <= HIT)), float(np.mean(np.any(miss <= HIT, axis=1)))


def timing(args, m, rows):
    """Curvature against descriptors and matching at args.timing_points points per surface."""
    n = args.timing_points
    surfaces = []
    for chain in "AB":
        points, normals, _, _ = surface(args.build, args.work, HPV, chain, spacing=0.35)
        if len(points) < n:
            sys.exit(f"1HPV chain {chain} sampled at 0.35 A has {len(points)} points, fewer than {n}")
        keep = np.sort(m.farthest_point_sample(points, n))
        xyz = os.path.join(args.work, f"timing_{chain}_{n}.xyz")
        np.savetxt(xyz, np.hstack([points[keep], normals[keep]]), fmt="%.6f")
        surfaces.append((points[keep], normals[keep], xyz))
    seconds_curvature, layers = 0.0, []
    for _, _, xyz in surfaces:
        out = xyz[:-4] + "_curvature"
        seconds_curvature += curvature(args.build, xyz, out)
        layers.append(layers_from_ply(read_ply(os.path.join(out, "curvatures.ply"))))
    start = time.time()
    (pa, na, _), (pb, nb, _) = surfaces
    ra = m.region_descriptors(pa, layers[0][0], m.farthest_point_sample(pa, CENTRES), normals=na,
                              center_normals=layers[0][1], rings=RINGS)
    rb = m.region_descriptors(pb, layers[1][0], m.farthest_point_sample(pb, CANDIDATES), normals=nb,
                              center_normals=layers[1][1], rings=RINGS)
    m.match_regions(ra, rb, top=10)
    seconds = time.time() - start
    name = f"1HPV A/B at {n}"
    print(f"{name:20} time: curvature of the two surfaces {seconds_curvature:.1f} s, descriptors and matching "
          f"{seconds:.1f} s ({seconds / seconds_curvature:.2f} of the curvature's)")
    rows.append({"pair": name, "method": "curvature of the two surfaces", "points_a": n, "points_b": n,
                 "seconds": seconds_curvature})
    rows.append({"pair": name, "method": "descriptors and matching", "points_a": n, "points_b": n,
                 "seconds": seconds})


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--build", required=True)
    parser.add_argument("--work", default="benchmark_matching_work")
    parser.add_argument("--csv", help="the CSV file of the results (default: WORK/benchmark_matching.csv)")
    parser.add_argument("--pairs", default="hpv,tii,hpv-buried,tii-buried")
    parser.add_argument("--no-fpfh", action="store_true")
    parser.add_argument("--timing-points", type=int, default=20000, help="points per surface of the timing; 0: none")
    args = parser.parse_args()
    sys.path.insert(0, os.path.join(os.path.abspath(args.build), "python"))
    from conformal_alpha_shapes import matching as m
    os.makedirs(args.work, exist_ok=True)
    csv_path = args.csv or os.path.join(args.work, "benchmark_matching.csv")
    rows = []
    print("pair                 method               top-1  top-10  seconds")
    for key in args.pairs.split(",") if args.pairs else []:
        pdb, chain_a, chain_b, complex_chains = PAIRS[key]
        if not os.path.exists(pdb):
            sys.exit(f"{pdb} is missing: install pymol-data (apt-get install pymol-data)")
        pa, na, va, xyz_a = surface(args.build, args.work, pdb, chain_a, complex_chains)
        pb, nb, vb, xyz_b = surface(args.build, args.work, pdb, chain_b)
        la, ca_normals = layers_from_ply(va)
        lb, cb_normals = layers_from_ply(vb)
        ca_a, ca_b = common_ca_atoms(pdb, chain_a, chain_b)
        r_true, t_true = m.fit_rigid(ca_a, ca_b)  # A onto B: the true places of A's centres on B
        centres = m.farthest_point_sample(pa, CENTRES)
        candidates = m.farthest_point_sample(pb, CANDIDATES)
        true_places = pa[centres] @ r_true.T + t_true
        name = os.path.basename(pdb)[:4].upper() + " " + (
            f"{chain_a} in {complex_chains}/{chain_b}" if complex_chains else f"{chain_a}/{chain_b}")
        sizes = {"pair": name, "points_a": len(pa), "points_b": len(pb)}

        start = time.time()
        ra = m.region_descriptors(pa, la, centres, normals=na, center_normals=ca_normals, rings=RINGS)
        rb = m.region_descriptors(pb, lb, candidates, normals=nb, center_normals=cb_normals, rings=RINGS)
        matches = m.match_regions(ra, rb, top=10)
        seconds = time.time() - start
        for method, ranked in (("curvature rings", matches.candidates), ("re-ranked", matches.reranked)):
            miss = np.linalg.norm(pb[ranked] - true_places[:, None, :], axis=2)
            top1, top10 = float(np.mean(miss[:, 0] <= HIT)), float(np.mean(np.any(miss <= HIT, axis=1)))
            shown = seconds if ranked is matches.candidates else 0
            print(f"{name:20} {method if ranked is matches.candidates else '  ' + method:20} {top1:5.3f}  "
                  f"{top10:5.3f}  {shown:7.1f}")
            rows.append(dict(sizes, method=method, top1=top1, top10=top10,
                             seconds=seconds if ranked is matches.candidates else ""))
        placed = matches.transform(ca_b)
        rmsd = float(np.sqrt(np.mean(np.sum((placed - ca_a) ** 2, axis=1))))
        print(f"{name:20} registration B onto A: CA RMSD {rmsd:.2f} A, {matches.consistent:.0%} of the matches"
              " consistent")
        rows.append(dict(sizes, method="registration", ca_rmsd=rmsd, consistent=float(matches.consistent)))
        # the curvature timed again now, the machine as loaded as for the matching just before
        seconds_curvature = sum(curvature(args.build, xyz, os.path.join(args.work, "timing")) for xyz in (xyz_a, xyz_b))
        print(f"{name:20} time: curvature of the two surfaces ({len(pa)} + {len(pb)} points) "
              f"{seconds_curvature:.1f} s, descriptors and matching ({len(pa)} + {len(pb)} points) {seconds:.1f} s")
        rows.append(dict(sizes, method="curvature of the two surfaces", seconds=seconds_curvature))

        if not args.no_fpfh:
            start = time.time()
            fa, fb = fpfh(pa, na, 10.0), fpfh(pb, nb, 10.0)
            d = m.chi_square_distances(fa[centres], fb[candidates])
            top1, top10 = rates(d, true_places, pb[candidates])
            seconds = time.time() - start
            print(f"{name:20} {'FPFH 10 A':20} {top1:5.3f}  {top10:5.3f}  {seconds:7.1f}")
            rows.append(dict(sizes, method="FPFH 10 A", top1=top1, top10=top10, seconds=seconds))
            start = time.time()
            fa, fb = fpfh(pa, na, 3.0), fpfh(pb, nb, 3.0)
            da = ring_average(pa, fa, centres, RINGS)
            db = ring_average(pb, fb, candidates, RINGS)
            d = m.chi_square_distances(da, db)
            top1, top10 = rates(d, true_places, pb[candidates])
            seconds = time.time() - start
            print(f"{name:20} {'FPFH rings':20} {top1:5.3f}  {top10:5.3f}  {seconds:7.1f}")
            rows.append(dict(sizes, method="FPFH rings", top1=top1, top10=top10, seconds=seconds))

        if key == "hpv":
            # invariance: a rotated, translated copy of A against A
            angle = 1.1
            rot = np.array([[np.cos(angle), -np.sin(angle), 0], [np.sin(angle), np.cos(angle), 0], [0, 0, 1]])
            rot = rot @ np.array([[1, 0, 0], [0, np.cos(0.7), -np.sin(0.7)], [0, np.sin(0.7), np.cos(0.7)]])
            moved = pa @ rot.T + np.array([25.0, -40.0, 13.0])
            base = os.path.join(args.work, "moved")
            np.savetxt(base + ".xyz", np.hstack([moved, na @ rot.T]), fmt="%.5f")
            curvature(args.build, base + ".xyz", base + "_curvature")
            lc, cc_normals = layers_from_ply(read_ply(os.path.join(base + "_curvature", "curvatures.ply")))
            rc = m.region_descriptors(moved, lc, m.farthest_point_sample(moved, CANDIDATES, first=17),
                                      normals=na @ rot.T, center_normals=cc_normals, rings=RINGS)
            d = m.histogram_distances(ra, rc)
            top1, top10 = rates(d, moved[centres], moved[rc.centers])
            print(f"{name:20} {'rotated copy of A':20} {top1:5.3f}  {top10:5.3f}")
            rows.append(dict(sizes, method="rotated copy of A", top1=top1, top10=top10, points_b=len(moved)))

    if args.timing_points > 0:
        timing(args, m, rows)
    write_csv(csv_path, rows)
    print(f"results in {csv_path}")


if __name__ == "__main__":
    main()
