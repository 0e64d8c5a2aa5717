#!/usr/bin/env python3
"""Growth with N of the default job, from benchmark_pipeline's CSV, as an SVG
plot for the manual: processor time per point (microseconds, log scale) of
the Delaunay build, of each stage of the job, of the whole job and of jet
fitting, against the number of points (log scale), one panel per input
surface. Python's standard library only.

    plot_pipeline.py benchmark_pipeline.csv pipeline_growth.svg
"""
import csv
import math
import sys

STAGES = [  # (label, how to find its rows, color)
    ("Delaunay build", lambda r: r["process"] == "delaunay", "#000000"),
    ("construction", lambda r: r["stage"].startswith("Multiscale_curvatures construction"), "#1f77b4"),
    ("automatic scale", lambda r: r["stage"].startswith("scale_value(Scale::automatic"), "#ff7f0e"),
    ("extraction", lambda r: r["stage"] == "extract_surface", "#2ca02c"),
    ("curvature", lambda r: r["stage"].startswith("estimate_curvatures"), "#d62728"),
    ("whole job", lambda r: r["group"] == "total", "#9467bd"),
    ("jet fitting, 120 nb", lambda r: r["process"] == "jet", "#8c564b"),
]


def read(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(line for line in f if not line.startswith("#")))


def series(rows, surface):
    """{label: [(n, cpu us per point)]}, stages summed per n."""
    out = {}
    for label, match, _ in STAGES:
        by_n = {}
        for r in rows:
            if r["input"] == surface and match(r):
                n = int(r["n"])
                by_n[n] = by_n.get(n, 0.0) + float(r["cpu_s"]) * 1e6 / n
        out[label] = sorted(by_n.items())
    return out


def main(csv_path, svg_path):
    rows = read(csv_path)
    surfaces = [s for s in dict.fromkeys(r["input"] for r in rows)
                if len({r["n"] for r in rows if r["input"] == s}) > 1]
    width, height, margin = 460, 340, 60
    parts = ['<svg xmlns="http://www.w3.org/2000/svg" width="%d" height="%d" font-family="sans-serif" '
             'font-size="11">' % (width * len(surfaces), height + 110)]
    values = [v for s in surfaces for pts in series(rows, s).values() for _, v in pts if v > 0]
    ns = [int(r["n"]) for r in rows if r["input"] in surfaces]
    y_lo, y_hi = 10 ** math.floor(math.log10(min(values))), 10 ** math.ceil(math.log10(max(values)))
    x_lo, x_hi = 10 ** math.floor(math.log10(min(ns))), 10 ** math.ceil(math.log10(max(ns)))
    for k, surface in enumerate(surfaces):
        ox = k * width

        def x(n):
            return ox + margin + (width - 1.5 * margin) * math.log(n / x_lo) / math.log(x_hi / x_lo)

        def y(v):
            return height - margin + 20 - (height - margin) * math.log(v / y_lo) / math.log(y_hi / y_lo)

        parts.append('<text x="%d" y="14" font-weight="bold">%s</text>' % (ox + margin, surface))
        e = math.log10(x_lo)
        while 10 ** e <= x_hi:
            n = 10 ** e
            parts.append('<line x1="%.1f" y1="%.1f" x2="%.1f" y2="%.1f" stroke="#ddd"/>' % (x(n), y(y_lo), x(n), y(y_hi)))
            parts.append('<text x="%.1f" y="%.1f" text-anchor="middle">%s</text>' % (x(n), y(y_lo) + 14, "{:,}".format(int(n))))
            e += 1
        e = math.log10(y_lo)
        while 10 ** e <= y_hi:
            v = 10 ** e
            parts.append('<line x1="%.1f" y1="%.1f" x2="%.1f" y2="%.1f" stroke="#ddd"/>' % (x(x_lo), y(v), x(x_hi), y(v)))
            parts.append('<text x="%.1f" y="%.1f" text-anchor="end">%g</text>' % (x(x_lo) - 4, y(v) + 4, v))
            e += 1
        parts.append('<text x="%.1f" y="%.1f" text-anchor="middle">points</text>' % ((x(x_lo) + x(x_hi)) / 2, y(y_lo) + 28))
        parts.append('<text x="%.1f" y="%.1f" transform="rotate(-90 %.1f %.1f)" text-anchor="middle">'
                     'processor time per point (us)</text>' % (ox + 14, (y(y_lo) + y(y_hi)) / 2, ox + 14, (y(y_lo) + y(y_hi)) / 2))
        for label, _, color in STAGES:
            pts = [(n, v) for n, v in series(rows, surface)[label] if v > 0]
            if not pts:
                continue
            parts.append('<polyline fill="none" stroke="%s" stroke-width="2" points="%s"/>'
                         % (color, " ".join("%.1f,%.1f" % (x(n), y(v)) for n, v in pts)))
            for n, v in pts:
                parts.append('<circle cx="%.1f" cy="%.1f" r="2.5" fill="%s"/>' % (x(n), y(v), color))
    for i, (label, _, color) in enumerate(STAGES):
        lx, ly = margin + (i % 4) * 190, height + 50 + (i // 4) * 18
        parts.append('<line x1="%d" y1="%d" x2="%d" y2="%d" stroke="%s" stroke-width="2"/>' % (lx, ly - 4, lx + 20, ly - 4, color))
        parts.append('<text x="%d" y="%d">%s</text>' % (lx + 26, ly, label))
    parts.append("</svg>")
    with open(svg_path, "w") as f:
        f.write("\n".join(parts) + "\n")


if __name__ == "__main__":
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    main(sys.argv[1], sys.argv[2])
