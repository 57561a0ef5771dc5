#!/usr/bin/env python3
"""Pose errors of a planar-mapper run against indoor-sim's true poses.

Usage: pose_errors.py TRUE_POSES.txt POSES.txt [SUMMARY.json]
Prints one JSON object: ate_m (RMS position error after the best rigid 2D
alignment, as map-eval's pose_ate_m), max_m; with SUMMARY.json and loop
closure on, loops (accepted closures) and worst_loop_m (the largest distance
between a closure's match and the same relative pose of the true trajectory,
without the component along the closure's free_axis, which it leaves open).
Pure Python.
"""
import bisect
import json
import math
import sys


def load(path):
    out = []
    for line in open(path):
        if line.strip() and not line.startswith("#"):
            f = line.split()
            out.append((float(f[0]), float(f[1]), float(f[2]), float(f[4])))
    return out


def wrap(a):
    return math.atan2(math.sin(a), math.cos(a))


def at(trajectory, times, t):
    i = bisect.bisect_left(times, t)
    if i < len(times) and abs(times[i] - t) < 1e-6:
        return trajectory[i]
    if i == 0 or i == len(times):
        sys.exit("pose_errors: %.6f outside the true trajectory" % t)
    a, b = trajectory[i - 1], trajectory[i]
    s = (t - a[0]) / (b[0] - a[0])
    return (t, a[1] + s * (b[1] - a[1]), a[2] + s * (b[2] - a[2]), a[3] + s * wrap(b[3] - a[3]))


def between(a, b):
    c, s = math.cos(a[3]), math.sin(a[3])
    dx, dy = b[1] - a[1], b[2] - a[2]
    return (c * dx + s * dy, -s * dx + c * dy, wrap(b[3] - a[3]))


def ate(truth, times, estimate):
    p = [(e[1], e[2]) for e in estimate]
    q = [at(truth, times, e[0])[1:3] for e in estimate]
    n = len(p)
    mp = (sum(x for x, _ in p) / n, sum(y for _, y in p) / n)
    mq = (sum(x for x, _ in q) / n, sum(y for _, y in q) / n)
    sc = sum((a[0] - mp[0]) * (b[0] - mq[0]) + (a[1] - mp[1]) * (b[1] - mq[1]) for a, b in zip(p, q))
    ss = sum((a[0] - mp[0]) * (b[1] - mq[1]) - (a[1] - mp[1]) * (b[0] - mq[0]) for a, b in zip(p, q))
    th = math.atan2(ss, sc)
    c, s = math.cos(th), math.sin(th)
    err = [math.hypot(c * (a[0] - mp[0]) - s * (a[1] - mp[1]) + mq[0] - b[0],
                      s * (a[0] - mp[0]) + c * (a[1] - mp[1]) + mq[1] - b[1]) for a, b in zip(p, q)]
    return math.sqrt(sum(e * e for e in err) / n), max(err)


def main():
    if len(sys.argv) not in (3, 4):
        sys.exit(__doc__)
    truth = load(sys.argv[1])
    times = [p[0] for p in truth]
    rms, worst = ate(truth, times, load(sys.argv[2]))
    out = {"ate_m": rms, "max_m": worst}
    if len(sys.argv) == 4:
        loops = json.load(open(sys.argv[3]))["poses"].get("loop_closure")
        if loops is not None:
            errors = []
            for c in loops["closures"]:
                t = between(at(truth, times, c["older_t"]), at(truth, times, c["newer_t"]))
                ex, ey = t[0] - c["x_m"], t[1] - c["y_m"]
                ax, ay = c.get("free_axis", (0.0, 0.0))
                along = ex * ax + ey * ay  # a free axis's error does not count
                errors.append(math.hypot(ex - along * ax, ey - along * ay))
            out["loops"] = len(errors)
            out["worst_loop_m"] = max(errors, default=0.0)
    print(json.dumps(out))


if __name__ == "__main__":
    main()
