#!/usr/bin/env python3
"""How often `icacam loop` finds the hidden effects of `icacam synth --effect ... --radii` sets.

    python3 data/loop/hidden_effects.py EFFECTS FIRST_SEED LAST_SEED [ICACAM]

EFFECTS is one --effect value (camera,material); ICACAM defaults to build/host_tools/icacam.
Per seed: the effects the loop added (name, reading, held-out RMS after it) and why it
stopped; then in how many runs it added exactly the true effects, each in its physical form,
and how many of the camera factors and materials' n it states lie within their U (k = 2) of
truth.csv.
"""
import csv
import os
import re
import subprocess
import sys
import tempfile

EXPECTED = {'camera': (('camera_id',), 'scale'), 'material': (('material',), 'n'),
            'speed': (('press_speed_mm_s',), 'process'), 'drift': (('sequence',), 'drift'),
            'process': (('reduction', 'h_final_mm'), 'fe_slope'), 'optical': (('lens',), 'scale'),
            'speed_material': (('press_speed_mm_s_by_material',), 'process')}


def run(icacam, effects, seed, work):
    d = os.path.join(work, f'{effects.replace(",", "_")}_{seed}')
    subprocess.run([icacam, 'synth', '--out', d, '--effect', effects, '--count', '60', '--seed', str(seed),
                    '--radii'], check=True, capture_output=True)
    out = subprocess.run([icacam, 'loop', '--manifest', d + '/manifest.csv', '--report', d + '/report',
                          '--model', 'paper'], check=True, capture_output=True, text=True).stdout
    return d, out, re.findall(r'^effect \d+ (\S+) (\S+) cv_rms \S+ -> (\S+)', out, re.M)


def main():
    effects, first, last = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
    icacam = sys.argv[4] if len(sys.argv) > 4 else 'build/host_tools/icacam'
    want = [EXPECTED[e] for e in effects.split(',') if e != 'null']
    exact = estimates = within = 0
    with tempfile.TemporaryDirectory() as work:
        for seed in range(first, last + 1):
            d, out, added = run(icacam, effects, seed, work)
            found = sum(any(n in names and r == reading for n, r, _ in added) for names, reading in want)
            ok = found == len(want) and len(added) == len(want)
            exact += ok
            stopped = re.search(r'^stopped (.*)$', out, re.M)
            print(seed, 'ok ' if ok else 'NOT', added, stopped.group(1) if stopped else '')
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
    print(f'{effects}: exactly the true effects in {exact} of {last - first + 1} runs; '
          f'{within} of {estimates} camera factors and n within U (k = 2)')


if __name__ == '__main__':
    main()
