"""One row of doc/refinement-results.md: the EM's map (argv[1]) against the
refined map (argv[2]), both scored by map-eval (eval.json, summary.json)."""
import json
import sys


def load(d, name):
    with open(f"{d}/{name}") as f:
        return json.load(f)


a, b = load(sys.argv[1], "eval.json"), load(sys.argv[2], "eval.json")
s = load(sys.argv[2], "summary.json")
ref = s["refinement"]


def pair(key, scale=100.0, fmt="%.1f"):
    def one(e):
        return (fmt + " / " + fmt) % (scale * e[key]["mean"], scale * e[key]["max"])

    return f"{one(a)} → {one(b)}"


before = {p["gt_id"]: p["normal_error_deg"] for p in a["per_surface"]}
growth = max((p["normal_error_deg"] - before[p["gt_id"]] for p in b["per_surface"]
              if p["gt_id"] in before), default=0.0)
def doors(e):
    d = [p["corner_error_closed_m"] for p in e["per_surface"] if p["kind"] == "door"]
    return 100 * sum(d) / len(d) if d else float("nan")


cells = [
    f"{a['surfaces']} → {b['surfaces']} / {b['gt_surfaces']}",
    pair("seam_gap_m"),
    f"{100 * a['corner_error_m']['mean']:.1f} → {100 * b['corner_error_m']['mean']:.1f}",
    f"{100 * a['corner_error_closed_m']['mean']:.1f} → {100 * b['corner_error_closed_m']['mean']:.1f}",
    f"{doors(a):.1f} → {doors(b):.1f} ({len(ref.get('openings', []))})",
    f"{a['normal_error_deg']['mean']:.3f} → {b['normal_error_deg']['mean']:.3f}",
    f"{growth:+.3f}",
    f"{len(ref['seams'])}, {ref['fused_pairs']} ({ref['termination']})",
]
print(" | ".join(cells))
