"""Top view of the default world's L corner: the EM's rectangles and the
refined ones against the ground truth (doc/refinement-results.md).
Usage: plot_seams.py EM_DIR REFINED_DIR GT_JSON OUT_PNG"""
import csv
import json
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

XLIM, YLIM = (28.0, 31.6), (-1.6, 2.0)


def rectangles(path):
    out = []
    with open(path) as f:
        for r in csv.DictReader(f):
            corners = [(float(r[f"x{i}"]), float(r[f"y{i}"]), float(r[f"z{i}"])) for i in range(4)]
            out.append((abs(float(r["nz"])) > 0.9, corners))
    return out


def draw(ax, rects, colour, width):
    for horizontal, c in rects:
        xs = [p[0] for p in c] + [c[0][0]]
        ys = [p[1] for p in c] + [c[0][1]]
        ax.plot(xs, ys, color=colour, lw=width, ls="--" if horizontal else "-")


def main():
    em_dir, ref_dir, gt_path, out = sys.argv[1:5]
    gt = json.load(open(gt_path))
    truth = [(abs(s["normal"][2]) > 0.9, [tuple(p) for p in s["corners"]])
             for s in gt["surfaces"] if s["kind"] in ("wall", "ceiling")]
    fig, axes = plt.subplots(1, 2, figsize=(10, 5), sharey=True)
    for ax, d, title in zip(axes, (em_dir, ref_dir), ("EM alone", "refined")):
        draw(ax, truth, "0.75", 5)
        draw(ax, rectangles(f"{d}/surfaces.csv"), "tab:red" if d == em_dir else "tab:blue", 1.2)
        ax.set_xlim(*XLIM)
        ax.set_ylim(*YLIM)
        ax.set_aspect("equal")
        ax.set_title(title)
        ax.set_xlabel("x (m)")
    axes[0].set_ylabel("y (m)")
    fig.suptitle("L corner, top view: walls solid, ceilings dashed; ground truth grey")
    fig.tight_layout()
    fig.savefig(out, dpi=110)


if __name__ == "__main__":
    main()
