#!/usr/bin/env python3
"""The performance tables of the manual ("The Default Job at N Points") and
of the README ("How it compares"), in Markdown, from benchmark_pipeline's
CSV files: one run with TBB's default threads, one with `--no-jet --threads
1`. `cmake --build build --target performance_tables` runs both and this.
Python's standard library only.

    performance_tables.py TWO_THREADS.csv ONE_THREAD.csv OUTPUT.md
"""
import csv
import sys

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

    def __init__(self, rows, surface):
        word = "noise" if surface == "noisy" else "clean"
        self.rows = [r for r in rows if word in r["input"] and r["input"].startswith("ellipsoid")]
        if not self.rows:
            raise ValueError("no %s ellipsoid in the CSV" % surface)
        self.n = int(self.rows[0]["n"])

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

    def threads(r, serial):
        return "%.1f s / %.1f s: %.2fx" % (serial.job_less_delaunay(), r.job_less_delaunay(),
                                          serial.job_less_delaunay() / r.job_less_delaunay())

    front = "advancing front: the package's"
    rows = [
        ["`Delaunay_triangulation_3` alone (the unit)"] + cells(lambda r, _: "%.2f s" % r.wall("delaunay")),
        ["construction: input hygiene, noise, smoothing, `Conformal_alpha_shape_3`"] + cells(construction),
        ["the automatic scale (the front grown once) + `extract_surface()`"]
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
        ["the job less a Delaunay build, one thread / two threads (second command)"] + cells(threads),
    ]
    return table(["{:,} points, two threads".format(two["noisy"].n), "noisy", "clean"], rows)


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


def runs(rows):
    return {s: Run(rows, s) for s in SURFACES}


def main(argv):
    if len(argv) != 4:
        sys.exit(__doc__)
    provenance, two_rows = read_csv(argv[1])
    _, one_rows = read_csv(argv[2])
    two, one = runs(two_rows), runs(one_rows)
    heading = "\n".join("    %s %s" % item for item in provenance.items())
    text = ("Measured with\n\n%s\n\n## The manual's \"The Default Job\"\n\n%s\n\n## The README's \"How it compares\"\n\n%s\n"
            % (heading, manual_table(two, one), readme_table(two)))
    with open(argv[3], "w") as f:
        f.write(text)
    print(text)


if __name__ == "__main__":
    main(sys.argv)
