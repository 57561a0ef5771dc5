#!/usr/bin/env python3
"""Plots a planar-mapper points.ply coloured by surface id (black = outlier
class): a front view (looking along +x) and a top view. Needs matplotlib and
numpy (Debian: python3-matplotlib).
Usage: plot_surfaces.py points.ply out.png TITLE [MAX_RANGE_M]
(MAX_RANGE_M: only points this close to the origin in x and y; with it the
top view is drawn with a larger marker, for sparse lidar sweeps)"""
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np


def read_points(path):
    with open(path, "rb") as f:
        header = b""
        while not header.endswith(b"end_header\n"):
            header += f.read(1)
        dtype = np.dtype([("x", "<f4"), ("y", "<f4"), ("z", "<f4"), ("scan", "<i4"),
                          ("beam", "<i4"), ("surface", "<i4")])
        return np.frombuffer(f.read(), dtype=dtype)


def main():
    points = read_points(sys.argv[1])
    size = 0.4
    if len(sys.argv) > 4:
        reach = float(sys.argv[4])
        points = points[(np.abs(points["x"]) <= reach) & (np.abs(points["y"]) <= reach)]
        size = 2.0
    ids = np.unique(points["surface"])
    rng = np.random.default_rng(7)
    colours = {i: rng.uniform(0.15, 0.95, 3) for i in ids}
    colours[-1] = np.zeros(3)
    c = np.array([colours[i] for i in points["surface"]])
    step = max(1, len(points) // 60000)
    sel = slice(None, None, step)
    fig, ax = plt.subplots(1, 2, figsize=(13, 5.5))
    ax[0].scatter(-points["y"][sel], points["z"][sel], c=c[sel], s=size)
    ax[0].set_title("front view (left-right, up)")
    ax[1].scatter(-points["y"][sel], points["x"][sel], c=c[sel], s=size)
    ax[1].set_title("top view (left-right, depth)")
    for a in ax:
        a.set_aspect("equal")
        a.set_xlabel("m")
    fig.suptitle(sys.argv[3] if len(sys.argv) > 3 else "")
    plt.tight_layout()
    plt.savefig(sys.argv[2], dpi=70)


if __name__ == "__main__":
    main()
