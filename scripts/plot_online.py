#!/usr/bin/env python3
"""Plots a planar-mapper online.csv: EM time per scan and the number of
surfaces against the scan index. Needs matplotlib (Debian: python3-matplotlib).
Usage: plot_online.py online.csv out.png TITLE"""
import csv
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt


def main():
    rows = list(csv.DictReader(open(sys.argv[1])))
    n = list(range(len(rows)))
    ms = [float(r["em_ms"]) for r in rows]
    surfaces = [int(r["surfaces"]) for r in rows]
    fig, ax = plt.subplots(2, 1, figsize=(11, 6), sharex=True)
    ax[0].plot(n, ms, ",", alpha=0.6, label="EM update per scan")
    window = 101
    med = []
    for i in range(len(ms)):
        part = sorted(ms[max(0, i - window // 2): i + window // 2 + 1])
        med.append(part[len(part) // 2])
    ax[0].plot(n, med, "-", color="black", label="running median (101 scans)")
    ax[0].set_ylabel("ms")
    ax[0].set_yscale("log")
    ax[0].legend(loc="upper right")
    ax[1].plot(n, surfaces, "-")
    ax[1].set_ylabel("surfaces")
    ax[1].set_xlabel("structure scan (in feeding order)")
    fig.suptitle(sys.argv[3] if len(sys.argv) > 3 else "")
    plt.tight_layout()
    plt.savefig(sys.argv[2], dpi=70)


if __name__ == "__main__":
    main()
