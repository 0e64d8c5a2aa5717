#!/usr/bin/python3
"""Multi-scale curvature of a scan from Python: read the bundled bunny with
numpy, compute every point's curvature at five neighborhoods with a text
progress bar, save the values as the program's curvatures.ply and, when
Debian's python3-matplotlib is installed, a picture of the mean curvature.

    PYTHONPATH=build/python /usr/bin/python3 \
        examples/Conformal_alpha_shapes_3/python/curvature_of_a_scan.py [points] [output_folder]
"""
import os
import sys

import numpy as np

import conformal_alpha_shapes as cas

HERE = os.path.dirname(os.path.abspath(__file__))


def text_bar(stage, fraction):
    filled = int(30 * fraction)
    print(f"\r[{'#' * filled}{'.' * (30 - filled)}] {100 * fraction:3.0f}% {stage:<28}", end="", flush=True)
    if fraction == 1:
        print()


def save_picture(points, result, layer, path):
    try:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
    except ImportError:
        print("no picture: install python3-matplotlib")
        return
    H = result[layer].H
    limit = np.nanpercentile(np.abs(H), 95)
    figure = plt.figure(figsize=(6, 6))
    axes = figure.add_subplot(projection="3d")
    shown = axes.scatter(points[:, 0], points[:, 2], points[:, 1], c=H, cmap="coolwarm", vmin=-limit, vmax=limit,
                         s=2)
    axes.set_axis_off()
    axes.view_init(elev=10, azim=-70)
    figure.colorbar(shown, shrink=0.6, label=f"H ({layer})")
    figure.savefig(path, dpi=120, bbox_inches="tight")
    print(f"picture of H_{layer} in {path}")


def main():
    output = sys.argv[2] if len(sys.argv) > 2 else "curvature_of_a_scan_out"
    if len(sys.argv) > 1:  # any format the program reads: .xyz, .pwn, .ply, .off, .obj
        points, _ = cas.read_point_cloud(sys.argv[1])
    else:  # the bundled bunny: a line with the number of points, then x y z per line
        points = np.loadtxt(os.path.join(HERE, "..", "data", "bunny_5000.xyz"), skiprows=1)
    result = cas.multiscale_curvatures(points, progress=text_bar)
    print(f"{len(points)} points, spacing {result.spacing:.4g}, noise {result.noise:.3f} spacings, "
          f"layers {', '.join(result.layers)}")
    for name in result.layers:
        layer = result[name]
        print(f"  {name:6} a = {layer.a:.4g}  median H = {np.nanmedian(layer.H):.4g}")
    os.makedirs(output, exist_ok=True)
    result.write_ply(os.path.join(output, "curvatures.ply"))
    save_picture(points, result, "r4s", os.path.join(output, "mean_curvature_r4s.png"))


if __name__ == "__main__":
    main()
