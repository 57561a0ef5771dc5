#!/usr/bin/env python3
"""Writes doc/performance.md from scripts/bench.sh's outputs.
Usage: bench_report.py WORK_DIR REPS OUT.md DATE COMMIT NPROC CPU"""
import json
import os
import statistics
import sys


def medians(path):
    """name -> (real_time in its unit, unit, counters) of the median aggregates."""
    out = {}
    for b in json.load(open(path))["benchmarks"]:
        if b.get("aggregate_name") == "median":
            out[b["run_name"]] = b
    return out


def ns_per_item(b):
    scale = {"ns": 1, "us": 1e3, "ms": 1e6, "s": 1e9}[b["time_unit"]]
    return 1e9 / b["items_per_second"] if "items_per_second" in b else b["real_time"] * scale


def stage_table(work, reps):
    rows = ["| poses | total | read | pose (ICP) | map (points, raw mesh) | EM | refinement | texture "
            "| write | EM per scan p50 / p99 (ms) |", "|---|---|---|---|---|---|---|---|---|---|"]
    shares = {}
    for poses in ("true", "icp"):
        runs = [json.load(open(os.path.join(work, "map-%s-%d" % (poses, r), "summary.json")))
                for r in range(1, reps + 1)]
        med = {k: statistics.median(r["timing_s"].get(k, 0.0) for r in runs)
               for k in ("total", "read", "pose", "map", "em", "refine", "texture", "write")}
        p50 = statistics.median(r["em_per_scan_ms"]["p50"] for r in runs)
        p99 = statistics.median(r["em_per_scan_ms"]["p99"] for r in runs)
        rows.append("| %s | %s | %.2f / %.2f |" % (
            poses, " | ".join("%.2f s (%.0f %%)" % (med[k], 100 * med[k] / med["total"]) if k != "total"
                              else "%.2f s" % med[k] for k in med), p50, p99))
        shares[poses] = med
        med["em_p99"] = p99
    return "\n".join(rows), shares


def main():
    work, reps, out, date, commit, nproc, cpu = sys.argv[1:8]
    reps = int(reps)
    b = medians(os.path.join(work, "em_steps.json"))
    b.update(medians(os.path.join(work, "online_em.json")))
    lines = ["| benchmark | what one item is | median time per item | counters |", "|---|---|---|---|"]
    what = {"BM_EStep": "a point-surface pair (E-step, eqs. 17-18)",
            "BM_MStep": "a surface (M-step: moments, plane, rectangle)",
            "BM_PlaneFromMoments": "a plane from moments (eqs. 24-27)",
            "BM_RectangleFit": "a member point of the rectangle fit (eq. 29)",
            "BM_CoverageCut": "a member point of a coverage cut (model selection)",
            "BM_OnlineUpdatePerScan": "a scan of 181 points (online update)"}
    for name, r in b.items():
        base = name.split("/")[0]
        t = ns_per_item(r)
        tstr = "%.0f ns" % t if t < 1e4 else "%.1f µs" % (t / 1e3) if t < 1e7 else "%.1f ms" % (t / 1e6)
        counters = ", ".join("%s %.0f" % (k, v) for k, v in r.items()
                             if k in ("points", "pairs", "members", "surfaces"))
        lines.append("| `%s` | %s | %s | %s |" % (name.replace("_median", ""), what.get(base, ""), tstr, counters))
    stages, shares = stage_table(work, reps)
    tpl = open(os.path.join(os.path.dirname(__file__), "performance_template.md")).read()
    t = shares["icp"]
    e100, m100, fit = b["BM_EStep/100"], b["BM_MStep/100"], b["BM_RectangleFit/200"]
    online = b["BM_OnlineUpdatePerScan/iterations:600"]
    pairs_per_point = e100["pairs"] / e100["points"]
    members = e100["points"] / 3  # three surfaces share the points
    fit_us = ns_per_item(fit) * members / 1e3
    m_us = ns_per_item(m100) / 1e3
    open(out, "w").write(tpl.format(
        estep_ns="%.0f" % ns_per_item(e100), pairs_per_point="%.2f" % pairs_per_point,
        scan_estep_us="%.0f" % (181 * pairs_per_point * ns_per_item(e100) / 1e3),
        fit_ns="%.0f" % ns_per_item(fit), members="%.0f" % members, fit_us="%.0f" % fit_us,
        mstep_us="%.0f" % m_us, fit_share="%.0f" % (100 * fit_us / m_us),
        online_ms="%.2f" % (ns_per_item(online) / 1e6),
        em_p99_ms="%.2f" % shares["true"]["em_p99"],
        plane_ns="%.0f" % ns_per_item(b["BM_PlaneFromMoments"]),
        budget_factor="%.0f" % (200 / shares["true"]["em_p99"]), write_share="%.0f" % (100 * t["write"] / t["total"]),
        date=date, commit=commit, nproc=nproc, cpu=cpu, reps=reps, bench="\n".join(lines),
        stages=stages, pose_share="%.0f" % (100 * t["pose"] / t["total"]),
        em_share_true="%.0f" % (100 * shares["true"]["em"] / shares["true"]["total"]),
        cut_ns="%.0f" % ns_per_item(b["BM_CoverageCut/200"]),
        cut_over_fit="%.0f" % (ns_per_item(b["BM_CoverageCut/200"]) / ns_per_item(fit))))


if __name__ == "__main__":
    main()
