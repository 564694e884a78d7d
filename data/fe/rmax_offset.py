#!/usr/bin/env python3
"""The FE's R_max over the reference specimens' widest radius, fitted over n and mu.

    python3 data/fe/rmax_offset.py ../shared/data/devset [../shared/data/photoset ...]

The first set is fitted, the others are only checked. For every record: the FE base's R_max at
half height (data/fe/sweep_cax8r_c005_st1e5_tracked.csv, the 0.5 snapshot, bilinear in n and mu
and held at the grid's ends, as friction/grid.h reads it) over the truth's r_bulge_mm, less one,
at the manifest's n and the truth's mu. The fit is a plane in ln n and mu with their product
(least squares); it prints the coefficients friction/radii_consistency.cpp carries and the
residuals on every set. Standard library only.
"""
import csv
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
BASE = os.path.join(HERE, "sweep_cax8r_c005_st1e5_tracked.csv")


def fe_rmax_table():
    table = {}
    with open(BASE) as f:
        for row in csv.DictReader(f):
            if row["status"] == "ok" and abs(float(row["reduction"]) - 0.5) < 1e-9:
                table[(float(row["n"]), float(row["mu"]))] = float(row["r_max_mm"])
    return table


def axis_spot(values, x):
    if x <= values[0]:
        return 0, 0.0
    if x >= values[-1]:
        return len(values) - 2, 1.0
    for i in range(len(values) - 1):
        if values[i] <= x <= values[i + 1]:
            return i, (x - values[i]) / (values[i + 1] - values[i])
    raise ValueError(x)


def fe_rmax(table, n, mu):
    ns = sorted({k[0] for k in table})
    mus = sorted({k[1] for k in table})
    i, wi = axis_spot(ns, n)
    j, wj = axis_spot(mus, mu)
    v = 0.0
    for a, wa in ((i, 1 - wi), (i + 1, wi)):
        for b, wb in ((j, 1 - wj), (j + 1, wj)):
            if wa * wb > 0:
                v += wa * wb * table[(ns[a], mus[b])]
    return v


def records(folder, table):
    with open(os.path.join(folder, "manifest.csv")) as f:
        n_of = {r["id"]: float(r["n"]) for r in csv.DictReader(f)}
    out = []
    with open(os.path.join(folder, "truth.csv")) as f:
        for t in csv.DictReader(f):
            if abs(float(t.get("reduction", 0.5)) - 0.5) > 1e-6:
                continue
            n, mu = n_of[t["id"]], float(t["mu"])
            out.append((t["id"], n, mu, fe_rmax(table, n, mu) / float(t["r_bulge_mm"]) - 1))
    return out


def basis(n, mu):
    ln = math.log(n)
    return [1.0, ln, mu, ln * mu]


def least_squares(rows):
    xs = [basis(n, mu) for _, n, mu, _ in rows]
    ys = [o for *_, o in rows]
    k = len(xs[0])
    a = [[sum(x[p] * x[q] for x in xs) for q in range(k)] for p in range(k)]
    b = [sum(x[p] * y for x, y in zip(xs, ys)) for p in range(k)]
    for c in range(k):
        piv = max(range(c, k), key=lambda r: abs(a[r][c]))
        a[c], a[piv], b[c], b[piv] = a[piv], a[c], b[piv], b[c]
        for r in range(c + 1, k):
            f = a[r][c] / a[c][c]
            a[r] = [a[r][q] - f * a[c][q] for q in range(k)]
            b[r] -= f * b[c]
    coef = [0.0] * k
    for c in range(k - 1, -1, -1):
        coef[c] = (b[c] - sum(a[c][q] * coef[q] for q in range(c + 1, k))) / a[c][c]
    return coef


def main(argv):
    if len(argv) < 2:
        print(__doc__.strip().splitlines()[2].strip(), file=sys.stderr)
        return 2
    table = fe_rmax_table()
    sets = [(folder, records(folder, table)) for folder in argv[1:]]
    fitted = sets[0][1]
    coef = least_squares(fitted)
    print("c0 %.7f  c_ln_n %.7f  c_mu %.7f  c_ln_n_mu %.7f" % tuple(coef))
    print("n %.3f-%.3f  mu %.3f-%.3f over the fitted set" % (
        min(r[1] for r in fitted), max(r[1] for r in fitted), min(r[2] for r in fitted), max(r[2] for r in fitted)))
    for folder, rows in sets:
        if not rows:
            continue
        raw = [o for *_, o in rows]
        res = [o - sum(c * x for c, x in zip(coef, basis(n, mu))) for _, n, mu, o in rows]
        rms = lambda v: math.sqrt(sum(x * x for x in v) / len(v))
        print("%s: %d records; offset %.2f-%.2f %% (mean %.2f %%); left by the fit: RMS %.3f %%, at most %.3f %%" % (
            os.path.basename(os.path.normpath(folder)), len(rows), 100 * min(raw), 100 * max(raw),
            100 * sum(raw) / len(raw), 100 * rms(res), 100 * max(abs(x) for x in res)))
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv))
