#!/usr/bin/env python3
"""The upsetting case under *VISCO with a rate-sensitive flow curve, against *STATIC.

Reads the rows `icacam fe sweep` wrote for the rate-independent runs (--static) and for the
runs with a press speed (--visco; the case label carries _v<speed>_m<m>) and writes, per
(n, mu, reduction, speed, m), u of the tracked contact edge and its difference from the same
mesh's time-hardening run at m = 0 and the same speed, and from the *STATIC run; then the cost
of each run against the *STATIC run of its (n, mu). A faster press speed's u is also given
against the slowest speed's with the same m and CETOL. Standard library only.

    data/fe/studies/rate/upset.py --static S.csv --visco V.csv --out upset_summary.csv [--md FILE]
        [--work DIR]

--work: the sweeps' work directory; each case's job.sta there gives its increments and Newton
iterations, a cost that does not depend on what else the machine runs (wall_s does).
"""
import argparse
import csv
import os
import re

REDUCTIONS = ("0.4000", "0.5000", "0.6000")


def rows(path):
    with open(path, newline="") as f:
        return list(csv.DictReader(f))


def speed_m_and_cetol(label):
    """Press speed, m and CETOL from the case label (FeCase::label; CETOL 0.01 unless _ct)."""
    m = re.search(r"_v([0-9.e+-]+)_m([0-9.e+-]+)", label)
    ct = re.search(r"_ct([0-9.e+-]+)", label)
    return (float(m.group(1)) if m else 0.0, float(m.group(2)) if m else 0.0,
            float(ct.group(1)) if ct else (0.01 if m else 0.0))


def solver_cost(work, label):
    """(increments, Newton iterations) from the case's job.sta; ("", "") without one."""
    path = os.path.join(work, label, "job.sta") if work else ""
    if not path or not os.path.exists(path):
        return "", ""
    inc, its = 0, 0
    with open(path) as f:
        for line in f:
            v = line.split()
            if len(v) >= 4 and v[0] == "1" and v[1].isdigit() and v[3].isdigit():
                inc, its = int(v[1]), its + int(v[3])
    return inc, its


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--static", required=True)
    ap.add_argument("--visco", required=True)
    ap.add_argument("--out", required=True)
    ap.add_argument("--md")
    ap.add_argument("--work")
    a = ap.parse_args()
    u, wall, status, cost = {}, {}, {}, {}
    for path in (a.static, a.visco):
        for r in rows(path):
            v, m, ct = speed_m_and_cetol(r["case"])
            key = (float(r["n"]), float(r["mu"]), v, m, ct)
            wall[key] = float(r["wall_s"])
            cost[key] = solver_cost(a.work, r["case"])
            status[key] = r["status"] + (": " + r["message"] if r["message"] else "")
            if r["reduction"] in REDUCTIONS:
                u[key + (r["reduction"],)] = float(r["u_track_mm"])
    out = []
    for key in sorted(wall, key=lambda k: (k[0], -k[1], k[2] > 0, -k[4], k[2], k[3])):
        n, mu, v, m, ct = key
        for red in REDUCTIONS:
            if key + (red,) not in u:
                continue
            x = u[key + (red,)]
            ref0 = u.get((n, mu, v, 0.0, ct, red)) if v > 0 else None
            refs = u.get((n, mu, 0.0, 0.0, 0.0, red))
            slow = min((k[2] for k in wall if k[:2] == (n, mu) and k[3:] == (m, ct) and k[2] > 0), default=0.0)
            refv = u.get((n, mu, slow, m, ct, red)) if 0 < slow < v else None
            out.append({
                "n": n, "mu": mu, "step": "VISCO" if v > 0 else "STATIC", "press_speed_mm_s": v, "m": m, "cetol": ct,
                "reduction": float(red), "u_track_mm": "%.5f" % x,
                "du_vs_m0_mm": "%+.5f" % (x - ref0) if ref0 is not None else "",
                "du_vs_m0_pct": "%+.2f" % (100 * (x / ref0 - 1)) if ref0 else "",
                "du_vs_slowest_speed_mm": "%+.5f" % (x - refv) if refv is not None else "",
                "du_vs_slowest_speed_pct": "%+.2f" % (100 * (x / refv - 1)) if refv else "",
                "du_vs_static_mm": "%+.5f" % (x - refs) if refs is not None and v > 0 else "",
                "du_vs_static_pct": "%+.2f" % (100 * (x / refs - 1)) if refs and v > 0 else "",
                "wall_s": "%.1f" % wall[key],
                "wall_over_static": "%.2f" % (wall[key] / wall[(n, mu, 0.0, 0.0, 0.0)])
                if (n, mu, 0.0, 0.0, 0.0) in wall else "",
                "increments": cost[key][0], "iterations": cost[key][1],
                "iterations_over_static": "%.2f" % (cost[key][1] / cost[(n, mu, 0.0, 0.0, 0.0)][1])
                if cost[key][1] != "" and cost.get((n, mu, 0.0, 0.0, 0.0), ("", ""))[1] else "",
                "status": status[key]})
    with open(a.out, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(out[0].keys()), lineterminator="\n")
        w.writeheader()
        w.writerows(out)
    if a.md:
        with open(a.md, "w") as f:
            f.write("| n | mu | step | speed mm/s | m | CETOL | reduction | u mm | vs m 0 | vs slowest | vs STATIC | wall s |"
                    " / STATIC | iterations | / STATIC |\n")
            f.write("|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|\n")
            for r in out:
                f.write("| %g | %g | %s | %g | %g | %s | %g | %s | %s | %s | %s | %s | %s | %s | %s |\n" % (
                    r["n"], r["mu"], r["step"], r["press_speed_mm_s"], r["m"], "%g" % r["cetol"] if r["cetol"] else "",
                    r["reduction"], r["u_track_mm"],
                    (r["du_vs_m0_mm"] + " (" + r["du_vs_m0_pct"] + " %)") if r["du_vs_m0_mm"] else "",
                    (r["du_vs_slowest_speed_mm"] + " (" + r["du_vs_slowest_speed_pct"] + " %)")
                    if r["du_vs_slowest_speed_mm"] else "",
                    (r["du_vs_static_mm"] + " (" + r["du_vs_static_pct"] + " %)") if r["du_vs_static_mm"] else "",
                    r["wall_s"], r["wall_over_static"], r["iterations"], r["iterations_over_static"]))


if __name__ == "__main__":
    main()
