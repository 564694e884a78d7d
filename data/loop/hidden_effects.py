#!/usr/bin/env python3
"""How often `icacam loop` finds the hidden effects of `icacam synth --effect ... --radii` sets.

    python3 data/loop/hidden_effects.py EFFECTS FIRST_SEED LAST_SEED [ICACAM [SYNTH_ICACAM]]

EFFECTS is one --effect value (camera,material); ICACAM defaults to build/host_tools/icacam;
SYNTH_ICACAM (default ICACAM) draws the sets, so that two builds' loops can be run on one draw.
Per seed: the effects the loop added (name, reading, held-out RMS after it), the candidates it
could not separate from them, and why it stopped; for a run that missed an effect, what the
records could show of it (below). Then in how many runs it added exactly the true effects, each
in its physical form; in how many it added a false one; and how many of the camera factors and
materials' n it states lie within their U (k = 2) of truth.csv.

What the records could show of an effect: the μ it adds to each record (truth.csv's mu_*_shift)
against the records' scatter (the residual with every hidden effect's μ taken out), in the
effect's plain form (a value per camera or material, a line in the sequence, a line in ln v, a
line in ln v within the rate-sensitive material). `size/SE` is the effect in units of its
standard error on these records (the z it would have with no scatter drawn), `z alone` the F
test's z on this run's residual with every other hidden effect taken out exactly. Where `z alone`
lies below the family's critical z (about 3.6 for these sets at α = 0.01), these records cannot
show the effect whatever the loop does.
"""
import csv
import math
import os
import re
import subprocess
import sys
import tempfile

EXPECTED = {'camera': (('camera_id',), 'scale'), 'material': (('material',), 'n'),
            'speed': (('press_speed_mm_s',), 'process'), 'drift': (('sequence',), 'drift'),
            'process': (('reduction', 'h_final_mm'), 'fe_slope'), 'optical': (('lens',), 'scale'),
            'speed_material': (('press_speed_mm_s_by_material',), 'process')}
SHIFT = {'camera': 'mu_camera_shift', 'drift': 'mu_drift_shift', 'speed': 'mu_speed_shift',
         'speed_material': 'mu_speed_shift', 'material': 'mu_n_shift'}


def sse(rows, y):
    """Residual sum of squares of y's least squares in the design rows (normal equations)."""
    p = len(rows[0])
    a = [[sum(r[i] * r[j] for r in rows) for j in range(p)] + [sum(r[i] * v for r, v in zip(rows, y))]
         for i in range(p)]
    for c in range(p):
        piv = max(range(c, p), key=lambda k: abs(a[k][c]))
        a[c], a[piv] = a[piv], a[c]
        if abs(a[c][c]) < 1e-300:
            continue
        for k in range(p):
            if k != c:
                f = a[k][c] / a[c][c]
                a[k] = [x - f * z for x, z in zip(a[k], a[c])]
    q = [a[i][p] / a[i][i] if abs(a[i][i]) > 1e-300 else 0 for i in range(p)]
    return sum((v - sum(x * b for x, b in zip(r, q))) ** 2 for r, v in zip(rows, y))


def f_z(sse0, p0, sse1, p1, n):
    """The nested F test as a normal z (Wilson–Hilferty's approximation of F)."""
    d1, d2 = p1 - p0, n - p1
    if sse1 <= 0 or d1 < 1 or d2 < 1:
        return 0.0
    f = max(0.0, (sse0 - sse1) / d1) / (sse1 / d2)
    a, b = 2 / (9 * d1), 2 / (9 * d2)
    return ((1 - b) * f ** (1 / 3) - (1 - a)) / math.sqrt(b * f ** (2 / 3) + a)


def design(effect, manifest, truth):
    """The effect's plain form: one row of features per record."""
    n = len(manifest)
    if effect in ('camera', 'material'):
        key = 'camera_id' if effect == 'camera' else 'material'
        levels = sorted({m[key] for m in manifest})
        return [[float(m[key] == lv) for lv in levels] for m in manifest]
    if effect == 'drift':
        x = [float(m['sequence']) for m in manifest]
    else:
        x = [math.log(float(m['press_speed_mm_s'])) for m in manifest]
    mean = sum(x) / n
    if effect == 'speed_material':
        acting = {t['material'] for t in truth if float(t['speed_factor']) != 1}
        return [[1.0, (m['material'] in acting) * (v - mean)] for m, v in zip(manifest, x)]
    return [[1.0, v - mean] for v in x]


def shown(d, effects):
    """Per hidden effect: (size/SE, z alone) on this run's records."""
    truth = list(csv.DictReader(open(d + '/truth.csv')))
    manifest = list(csv.DictReader(open(d + '/manifest.csv')))
    records = list(csv.DictReader(open(d + '/report/records.csv')))
    y = [float(r['residual']) for r in records]
    n = len(y)
    known = [e for e in effects if e in SHIFT]
    shift = {e: [float(t[SHIFT[e]]) for t in truth] for e in known}
    noise = [v - sum(shift[e][i] for e in known) for i, v in enumerate(y)]
    one = [[1.0]] * n
    sigma = math.sqrt(sse(one, noise) / (n - 1))
    out = {}
    for e in known:
        rows = design(e, manifest, truth)
        size = math.sqrt(max(0.0, sse(one, shift[e]) - sse(rows, shift[e]))) / sigma
        alone = [v - sum(shift[f][i] for f in known if f != e) for i, v in enumerate(y)]
        out[e] = (size, f_z(sse(one, alone), 1, sse(rows, alone), len(rows[0]), n))
    return out


def run(icacam, effects, seed, work, synth):
    d = os.path.join(work, f'{effects.replace(",", "_")}_{seed}')
    subprocess.run([synth, 'synth', '--out', d, '--effect', effects, '--count', '60', '--seed', str(seed),
                    '--radii'], check=True, capture_output=True)
    out = subprocess.run([icacam, 'loop', '--manifest', d + '/manifest.csv', '--report', d + '/report',
                          '--model', 'paper'], check=True, capture_output=True, text=True).stdout
    return d, out, re.findall(r'^effect \d+ (\S+) (\S+) cv_rms \S+ -> (\S+)', out, re.M)


def main():
    effects, first, last = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
    icacam = sys.argv[4] if len(sys.argv) > 4 else 'build/host_tools/icacam'
    synth = sys.argv[5] if len(sys.argv) > 5 else icacam
    names = [e for e in effects.split(',') if e != 'null']
    want = [EXPECTED[e] for e in names]
    exact = false_runs = estimates = within = 0
    with tempfile.TemporaryDirectory() as work:
        for seed in range(first, last + 1):
            d, out, added = run(icacam, effects, seed, work, synth)
            hit = [any(n in cands and r == reading for n, r, _ in added) for cands, reading in want]
            true_added = sum(any(n in cands and r == reading for cands, reading in want) for n, r, _ in added)
            ok = all(hit) and len(added) == len(want)
            exact += ok
            false_runs += true_added < len(added)
            stopped = re.search(r'^stopped (.*)$', out, re.M)
            line = f'{seed} {"ok " if ok else "NOT"} {added}'
            for m in re.findall(r'^inseparable (.*)$', out, re.M):
                line += f' could not separate: {m}'
            print(line, stopped.group(1) if stopped else '')
            if not all(hit):
                figures = shown(d, names)
                for e, h in zip(names, hit):
                    if not h and e in figures:
                        print(f'    missed {e}: size/SE {figures[e][0]:.1f}, z alone {figures[e][1]:.1f}')
            truth = list(csv.DictReader(open(d + '/truth.csv')))
            camera = {t['camera_id']: 1 + float(t['camera_error']) for t in truth}
            n_true = {t['material']: float(t['n_true']) for t in truth}
            for p in csv.DictReader(open(d + '/report/physical.csv')):
                if p['reading'] == 'scale' and p['candidate'] == 'camera_id':
                    t = camera[p['level']]
                elif p['reading'] == 'n' and p['candidate'] == 'material':
                    t = n_true[p['level']]
                else:
                    continue
                estimates += 1
                within += abs(float(p['value']) - t) <= float(p['expanded'])
    print(f'{effects}: exactly the true effects in {exact} of {last - first + 1} runs; a false one added in '
          f'{false_runs}; {within} of {estimates} camera factors and n within U (k = 2)')


if __name__ == '__main__':
    main()
