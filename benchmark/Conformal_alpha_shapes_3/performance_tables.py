#!/usr/bin/env python3
"""The performance tables of the manual (section "Performance": the default
job, growth with size, threads, other tools) and of the README ("How it
compares"), in Markdown, from the benchmarks' CSV files: benchmark_pipeline
at several sizes with TBB's default threads, benchmark_pipeline with
`--no-jet --threads 1` at the largest size, and benchmark_peers.py. Each
table comes with the commands that reproduce it, read from the CSV files'
`# command` lines. Writes them all to OUTPUT.md and, with --manual and
--readme, replaces each generated block of those files: the lines between
`<!-- performance_tables: NAME -->` and `<!-- performance_tables: end -->`.
`cmake --build build --target performance_tables` runs the benchmarks and
this. Python's standard library only.

    performance_tables.py PIPELINE.csv ONE_THREAD.csv PEERS.csv OUTPUT.md [--manual FILE] [--readme FILE]
"""
import argparse
import csv
import os
import re

SURFACES = ("noisy", "clean")


def read_csv(path):
    """The provenance lines (`# key value`) as a dict, and the rows."""
    provenance, lines = {}, []
    with open(path, newline="") as f:
        for line in f:
            if line.startswith("# "):
                key, _, value = line[2:].rstrip("\n").partition(" ")
                provenance[key] = value
            else:
                lines.append(line)
    return provenance, list(csv.DictReader(lines))


class Run:
    """The rows of one input of one run, found by stage name."""

    def __init__(self, rows, surface, n=None):
        word = "noise" if surface == "noisy" else "clean"
        rows = [r for r in rows if word in r["input"] and r["input"].startswith("ellipsoid")]
        if not rows:
            raise ValueError("no %s ellipsoid in the CSV" % surface)
        self.n = n if n is not None else max(int(r["n"]) for r in rows)
        self.rows = [r for r in rows if int(r["n"]) == self.n]
        if not self.rows:
            raise ValueError("no %s ellipsoid of %d points in the CSV" % (surface, self.n))

    def row(self, process, stage_prefix=""):
        for r in self.rows:
            if r["process"] == process and r["stage"].startswith(stage_prefix):
                return r
        raise ValueError("no row %s / %s" % (process, stage_prefix))

    def value(self, process, stage_prefix, column):
        return float(self.row(process, stage_prefix)[column])

    def wall(self, process, stage_prefix=""):
        return self.value(process, stage_prefix, "wall_s")

    def ratio(self, process, stage_prefix=""):
        return self.value(process, stage_prefix, "wall_x_delaunay")

    def job(self):
        return self.wall("pipeline", "default job")

    def job_less_delaunay(self):
        return self.job() - self.wall("delaunay")


def mib(x):
    return "{:,.0f} MiB".format(x)


def table(header, rows):
    lines = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    lines += ["| " + " | ".join(r) + " |" for r in rows]
    return "\n".join(lines)


def manual_table(two, one):
    """The manual's table of the default job; `two` and `one` by surface."""
    def cells(f):
        return [f(two[s], one[s]) for s in SURFACES]

    def construction(r, _):
        text = "%.2fx" % r.ratio("pipeline", "Multiscale_curvatures construction")
        if r.row("parts", "denoise")["note"] == "not called for":
            return text + " (no smoothing)"
        return text + " (smoothing %.2fx, the shape %.2fx)" % (r.ratio("parts", "denoise"),
                                                               r.ratio("parts", "Conformal_alpha_shape_3 construction"))

    def files(r):
        return sum(float(x["wall_x_delaunay"]) for x in r.rows
                   if x["stage"].startswith("program: layer") or x["stage"].startswith("write "))

    def jet(r, _):
        return "%.1f s: the job takes %.2fx" % (r.wall("jet"), r.job() / r.wall("jet"))

    def peak(r, _):
        total = r.row("pipeline", "default job")
        return "**%s (%.2fx)**" % (mib(float(total["peak_added_mib"])), float(total["peak_added_x_delaunay"]))

    front = "advancing front: the package's"
    rows = [
        ["`Delaunay_triangulation_3` alone (the unit)"] + cells(lambda r, _: "%.2f s" % r.wall("delaunay")),
        ["construction: input hygiene, noise, smoothing, `Conformal_alpha_shape_3`"] + cells(construction),
        ["the automatic scale (the front grown once, the closing values of its vertices) + `extract_surface()`"]
        + cells(lambda r, _: "%.2fx + %.2fx" % (r.ratio("pipeline", "scale_value"), r.ratio("pipeline", "extract_surface"))),
        ["... the front alone, against a Delaunay build in its own process"]
        + cells(lambda r, _: "%.2f s (%.2fx)" % (r.wall("parts", front), r.ratio("parts", front))),
        ["`estimate_curvatures()`, five neighborhoods"]
        + cells(lambda r, _: "%.1f s (%.2fx)" % (r.wall("pipeline", "estimate_curvatures"),
                                                 r.ratio("pipeline", "estimate_curvatures"))),
        ["the layers and the binary files"] + cells(lambda r, _: "%.2fx" % files(r)),
        ["**the whole job**"] + cells(lambda r, _: "**%.1f s (%.2fx)**" % (r.job(), r.ratio("pipeline", "default job"))),
        ["CGAL jet fitting (`Monge_via_jet_fitting`, degree 2, 120 neighbors, serial)"] + cells(jet),
        ["**peak memory** (the largest stage's)"] + cells(peak),
    ]
    return table(["{:,} points, every core".format(two["noisy"].n), "noisy", "clean"], rows)


def readme_table(two):
    """The README's table, in the README's words and rounding."""
    noisy, clean = two["noisy"], two["clean"]

    def peak(r):
        total = r.row("pipeline", "default job")
        return mib(float(total["peak_added_mib"])), float(total["peak_added_x_delaunay"])

    rows = [
        ["the whole default job (automatic scale, surface, five neighborhoods, files)",
         "%.1f s, %.1fx the Delaunay build" % (noisy.job(), noisy.ratio("pipeline", "default job")),
         "%.1f s, %.1fx" % (clean.job(), clean.ratio("pipeline", "default job"))],
        ["CGAL jet fitting with 120 neighbors, one curvature per point",
         "%.1f s: the job takes %.2fx" % (noisy.wall("jet"), noisy.job() / noisy.wall("jet")),
         "%.1f s: %.2fx" % (clean.wall("jet"), clean.job() / clean.wall("jet"))],
        ["peak memory", "%s, %.1fx the Delaunay build's" % peak(noisy), "%s, %.1fx" % peak(clean)],
    ]
    return table(["{:,} points".format(noisy.n), "noisy", "clean"], rows).replace("|---|---|---|", "| --- | --- | --- |")


def growth_table(rows):
    """The whole job at each size of the first run, per point and against the Delaunay build."""
    lines = []
    for surface in SURFACES:
        for n in sorted({int(r["n"]) for r in rows if r["input"].startswith("ellipsoid")}):
            r = Run(rows, surface, n)
            total = r.row("pipeline", "default job")
            peak = float(total["peak_added_mib"])
            lines.append([surface, "{:,}".format(n), "%.2f s" % r.wall("delaunay"),
                          "%.1f s (%.2fx)" % (r.job(), r.ratio("pipeline", "default job")),
                          "%.1f us" % (1e6 * r.job() / n), mib(peak), "%.2f KiB" % (1024 * peak / n)])
    return table(["ellipsoid", "points", "Delaunay build", "whole job", "per point", "peak memory", "per point"],
                 lines)


THREADED_STAGES = (("construction (hygiene, noise, smoothing, the shape)", "Multiscale_curvatures construction"),
                   ("the automatic scale (the front grown once, the closing values of its vertices)", "scale_value"),
                   ("`extract_surface()`", "extract_surface"),
                   ("`estimate_curvatures()`, five neighborhoods", "estimate_curvatures"),
                   ("the binary files", "write "))


def threads_table(two, one):
    """Each stage with one thread against every core, at the largest size."""
    def cell(surface, f):
        a, b = f(one[surface]), f(two[surface])
        return "%.1f s / %.1f s: %.2fx" % (a, b, a / b)

    def stage_sum(prefix):
        return lambda r: sum(float(x["wall_s"]) for x in r.rows
                             if x["process"] == "pipeline" and x["stage"].startswith(prefix))

    lines = [[name] + [cell(s, stage_sum(prefix)) for s in SURFACES] for name, prefix in THREADED_STAGES]
    lines.append(["**the whole job less a Delaunay build**"] + [cell(s, Run.job_less_delaunay) for s in SURFACES])
    return table(["{:,} points: one thread / every core: speedup".format(two["noisy"].n), "noisy", "clean"], lines)


def read_peers(path):
    provenance, rows = read_csv(path)
    if not rows:
        raise ValueError("no rows in %s" % path)
    return provenance, rows


def percent(x):
    return "%.2f%%" % (100 * float(x)) if x not in ("", None) else "-"


def peers_table(rows):
    """benchmark_peers.py's rows: time, memory, accuracy and orientation."""
    lines = []
    for r in rows:
        lines.append([r["tool"] + (", " + r["setting"] if r["setting"] else ""),
                      "%s s (%sx)" % (r["wall_s"], r["wall_x_delaunay"]), "%s s" % r["cpu_s"],
                      mib(float(r["peak_mib"])), percent(r["median_relative_H_error"]),
                      percent(r["outward_share"]) + " (" + percent(r["majority_side_share"]) + ")"
                      if r["outward_share"] else "-"])
    return table(["{:,} noisy points".format(int(rows[0]["n"])), "wall (x Delaunay)", "processor", "peak memory",
                  "median error of abs(H)", "normals outward (majority side)"], lines)


def readme_peers_table(rows):
    """The README's short table of the tools: the program, jet fitting and CloudCompare's best radius."""
    package = next(r for r in rows if r["tool"].startswith("this package"))
    jet = next(r for r in rows if r["tool"].startswith("CGAL Monge"))
    cloudcompare = [r for r in rows if r["tool"] == "CloudCompare"]
    best = min(cloudcompare, key=lambda r: float(r["median_relative_H_error"]))
    lines = [["`conformal_curvature`, the default job (five neighborhoods, files)", "%s s" % package["wall_s"],
              mib(float(package["peak_mib"])), percent(package["median_relative_H_error"])],
             ["CGAL jet fitting, 120 neighbors", "%s s" % jet["wall_s"], mib(float(jet["peak_mib"])),
              percent(jet["median_relative_H_error"])],
             ["CloudCompare, normals and mean curvature, %s (its best)" % best["setting"], "%s s" % best["wall_s"],
              mib(float(best["peak_mib"])), percent(best["median_relative_H_error"])]]
    return table(["{:,} noisy points".format(int(rows[0]["n"])), "wall", "peak memory", "median error of abs(H)"],
                 lines).replace("|---|---|---|---|", "| --- | --- | --- | --- |")


# options whose value is a path: shown by its last component
PATH_OPTIONS = {"--csv", "--program", "--pipeline", "--cloudcompare"}
# options of where temporary files go: left out
TEMPORARY_OPTIONS = {"--tmp", "--folder"}


def reader_command(provenance):
    """The `# command` line as a reader types it in the build's benchmark folder."""
    words = provenance.get("command", "").split()
    if not words:
        return "(the CSV names no command)"
    out, k = [os.path.basename(words[0])], 1
    while k < len(words):
        word = words[k]
        if word in TEMPORARY_OPTIONS:
            k += 2
            continue
        out.append(word)
        if word in PATH_OPTIONS and k + 1 < len(words):
            out.append(os.path.basename(words[k + 1]))
            k += 1
        k += 1
    return " ".join(out)


def commands(*provenances):
    return "\n".join("    " + reader_command(p) for p in provenances)


BLOCK = re.compile(r"(<!-- performance_tables: (\w+) -->\n)(.*?)(<!-- performance_tables: end -->)", re.S)


def replace_blocks(path, blocks):
    """Replaces each block of `path` named in `blocks`; an error when the file names one that is not made."""
    with open(path) as f:
        text = f.read()
    found = set()

    def fill(match):
        name = match.group(2)
        if name not in blocks:
            raise ValueError("%s: no table named %s" % (path, name))
        found.add(name)
        return match.group(1) + blocks[name].rstrip("\n") + "\n" + match.group(4)

    text = BLOCK.sub(fill, text)
    if not found:
        raise ValueError("%s has no <!-- performance_tables: NAME --> block" % path)
    with open(path, "w") as f:
        f.write(text)
    print("%s: wrote %s" % (path, ", ".join(sorted(found))))


def runs(rows):
    return {s: Run(rows, s) for s in SURFACES}


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("pipeline", help="benchmark_pipeline's CSV, TBB's default threads, one or more sizes")
    parser.add_argument("one_thread", help="benchmark_pipeline's CSV, --threads 1, the largest size")
    parser.add_argument("peers", help="benchmark_peers.py's CSV")
    parser.add_argument("output", help="the Markdown file of every table")
    parser.add_argument("--manual", help="the manual whose generated blocks to replace")
    parser.add_argument("--readme", help="the README whose generated blocks to replace")
    args = parser.parse_args()
    provenance, two_rows = read_csv(args.pipeline)
    one_provenance, one_rows = read_csv(args.one_thread)
    peers_provenance, peer_rows = read_peers(args.peers)
    two, one = runs(two_rows), runs(one_rows)
    if two["noisy"].n != one["noisy"].n:
        raise ValueError("the one-thread run has %d points, the other's largest size %d"
                         % (one["noisy"].n, two["noisy"].n))
    manual = {
        "job": "%s\n\n%s\n" % (commands(provenance, one_provenance), manual_table(two, one)),
        "growth": "%s\n\n%s\n" % (commands(provenance), growth_table(two_rows)),
        "threads": "%s\n\n%s\n" % (commands(provenance, one_provenance), threads_table(two, one)),
        "peers": "%s\n\n%s\n" % (commands(peers_provenance), peers_table(peer_rows)),
    }
    readme = {"readme": readme_table(two) + "\n", "readme_peers": readme_peers_table(peer_rows) + "\n"}
    machine = provenance.get("machine", "unknown")
    text = "Measured on %s, commit %s\n\n" % (machine, provenance.get("commit", "unknown"))
    text += "".join("## manual: %s\n\n%s\n" % item for item in manual.items())
    text += "".join("## README: %s\n\n%s\n" % item for item in readme.items())
    with open(args.output, "w") as f:
        f.write(text)
    print(text)
    if args.manual:
        replace_blocks(args.manual, manual)
    if args.readme:
        replace_blocks(args.readme, readme)


if __name__ == "__main__":
    main()
