#!/usr/bin/env python3
"""Crops of the simulator's posters out of map textures, beside the poster
images: one row per map directory.
Usage: plot_posters.py GT.json OUT.png LABEL=MAP_DIR [LABEL=MAP_DIR ...]
Texture tiles are placed with map-eval's pose alignment (MAP_DIR/eval.json)."""
import csv
import json
import os
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.image as mpimg  # noqa: E402
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def alignment(d):
    path = os.path.join(d, "eval.json")
    a = json.load(open(path))["pose"]["alignment"] if os.path.exists(path) else {
        "yaw_deg": 0, "x": 0, "y": 0}
    yaw = np.radians(a["yaw_deg"])
    rot = np.array([[np.cos(yaw), -np.sin(yaw), 0], [np.sin(yaw), np.cos(yaw), 0], [0, 0, 1]])
    return rot, np.array([a["x"], a["y"], 0.0])


def crop(d, poster, margin_px=12):
    rot, t = alignment(d)
    corners = np.array(poster["corners"])
    centre = corners.mean(0)
    for row in csv.DictReader(open(os.path.join(d, "textures.csv"))):
        c = np.array([rot @ np.array([float(row["%s%d" % (k, i)]) for k in "xyz"]) + t
                      for i in range(4)])
        u, v = c[1] - c[0], c[3] - c[0]
        lu, lv = np.linalg.norm(u), np.linalg.norm(v)
        u, v = u / lu, v / lv
        if abs(np.dot(centre - c[0], np.cross(u, v))) > 0.2:
            continue
        s, tt = np.dot(centre - c[0], u) / lu, np.dot(centre - c[0], v) / lv
        if not (0 <= s <= 1 and 0 <= tt <= 1):
            continue
        img = mpimg.imread(os.path.join(d, row["file"]))
        h, w = img.shape[:2]
        xs = [np.dot(q - c[0], u) / lu * w for q in corners]
        ys = [(1 - np.dot(q - c[0], v) / lv) * h for q in corners]
        x0, x1 = int(max(0, min(xs) - margin_px)), int(min(w, max(xs) + margin_px))
        y0, y1 = int(max(0, min(ys) - margin_px)), int(min(h, max(ys) + margin_px))
        return img[y0:y1, x0:x1]
    return None


def main():
    gt_path, out = sys.argv[1], sys.argv[2]
    maps = [a.split("=", 1) for a in sys.argv[3:]]
    gt = json.load(open(gt_path))
    posters = gt["posters"]
    fig, ax = plt.subplots(len(maps) + 1, len(posters), figsize=(4.2 * len(posters),
                                                                   3.1 * (len(maps) + 1)))
    ax = np.atleast_2d(ax)
    for j, p in enumerate(posters):
        ax[0][j].imshow(mpimg.imread(os.path.join(os.path.dirname(gt_path), p["image"])))
        ax[0][j].set_title("poster %d (ground truth)" % p["id"], fontsize=10)
        for i, (label, d) in enumerate(maps):
            img = crop(d, p)
            if img is not None:
                ax[i + 1][j].imshow(img)
            ax[i + 1][j].set_title(label, fontsize=10)
    for a in ax.flat:
        a.axis("off")
    plt.tight_layout()
    plt.savefig(out, dpi=80)


if __name__ == "__main__":
    main()
