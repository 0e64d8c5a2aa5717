"""The CSV files of the Python benchmarks, headed by the same provenance lines
as the C++ benchmarks' (include/cas3_benchmark.h): `# commit`, `# machine`
and `# command`, so that a table made from one says what was measured where.
Python's standard library only.
"""
import csv
import os
import subprocess
import sys

SOURCE_DIR = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")


def _first_line(path, key):
    """The value of the first line of `path` that starts with `key`, or "unknown"."""
    try:
        with open(path) as f:
            for line in f:
                if line.startswith(key):
                    return line[len(key):].strip(" \t:\n")
    except OSError:
        pass
    return "unknown"


def provenance(argv=None):
    """The three provenance lines, without their line ends."""
    try:
        commit = subprocess.run(["git", "-C", SOURCE_DIR, "describe", "--always", "--dirty", "--tags"],
                                capture_output=True, text=True).stdout.strip() or "unknown"
    except OSError:
        commit = "unknown"
    machine = "%s, %d cores, %s" % (_first_line("/proc/cpuinfo", "model name"), os.cpu_count() or 0,
                                     _first_line("/proc/meminfo", "MemTotal"))
    return ["# commit " + commit, "# machine " + machine, "# command " + " ".join(sys.argv if argv is None else argv)]


def write_csv(path, columns, rows):
    """Writes the provenance lines, the header `columns` and `rows` (dicts or
    sequences) to `path`."""
    with open(path, "w", newline="") as f:
        f.write("\n".join(provenance()) + "\n")
        writer = csv.writer(f, lineterminator="\n")
        writer.writerow(columns)
        for row in rows:
            writer.writerow([row.get(c, "") for c in columns] if isinstance(row, dict) else row)
