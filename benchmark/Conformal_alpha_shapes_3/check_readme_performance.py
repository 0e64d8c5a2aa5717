#!/usr/bin/env python3
"""Whether the README's performance table ("How it compares") matches a fresh
run of benchmark_pipeline within a tolerance (default 10%): compares each
number of the README's table with the same number of the table that
performance_tables.py makes from the CSV, and prints those that differ.
Exits 1 when one differs, unless --warn-only. Run by the performance_tables
target (warning only) and by `cmake --build build --target
check_readme_performance` on the last run's CSV.

    check_readme_performance.py README.md TWO_THREADS.csv [--tolerance 0.1] [--warn-only]
"""
import argparse
import re
import sys

from performance_tables import read_csv, readme_table, runs

NUMBER = re.compile(r"\d[\d,]*(?:\.\d+)?")
HEADER = re.compile(r"^\| [\d,]+ points \| noisy \| clean \|")


def numbers(cell):
    return [float(x.replace(",", "")) for x in NUMBER.findall(cell)]


def rows_of(table_lines):
    """{first cell: the other cells} of a Markdown table, header included."""
    rows = {}
    for line in table_lines:
        cells = [c.strip() for c in line.strip().strip("|").split("|")]
        if cells and not set(cells[0]) <= set("- "):
            rows[cells[0]] = cells[1:]
    return rows


def readme_rows(path):
    """The rows of the README's table headed `| N points | noisy | clean |`."""
    with open(path) as f:
        lines = f.read().splitlines()
    first = next(i for i, l in enumerate(lines) if HEADER.match(l))
    end = first
    while end < len(lines) and lines[end].startswith("|"):
        end += 1
    return rows_of(lines[first:end])


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("readme")
    parser.add_argument("csv", help="benchmark_pipeline's CSV, TBB's default threads")
    parser.add_argument("--tolerance", type=float, default=0.1)
    parser.add_argument("--warn-only", action="store_true")
    args = parser.parse_args()
    provenance, rows = read_csv(args.csv)
    fresh = list(rows_of(readme_table(runs(rows)).splitlines()).items())
    readme = readme_rows(args.readme)
    print("%s against %s (%s)" % (args.readme, args.csv, provenance.get("commit", "commit unknown")))
    if numbers(next(iter(readme))) != numbers(fresh[0][0]):
        print("note: the README's table is of %s, the fresh run of %s" % (next(iter(readme)), fresh[0][0]))
    differing = 0
    for name, cells in fresh[1:]:
        if name not in readme:
            print("missing from the README: %s" % name)
            differing += 1
            continue
        for column, (old, new) in enumerate(zip(readme[name], cells)):
            for a, b in zip(numbers(old), numbers(new)):
                if abs(b - a) > args.tolerance * abs(a):
                    print("differs by more than %g%%: %s, %s: README %g, fresh %g"
                          % (100 * args.tolerance, name, ("noisy", "clean")[column], a, b))
                    differing += 1
    print("%d figure(s) differ" % differing if differing else "every figure within %g%%" % (100 * args.tolerance))
    if differing and not args.warn_only:
        sys.exit(1)


if __name__ == "__main__":
    main()
