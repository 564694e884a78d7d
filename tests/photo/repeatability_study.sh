#!/usr/bin/env bash
# Repeatability of the reading on the committed photographs (tests/data/photo, or the folder
# DIR with its manifest.csv and truth.csv, such as a reference set): each frame
# measured as committed, then again with DRAWS fresh draws of sensor noise (1 grey level,
# seeded), mirrored, turned a quarter, at 0.7 and 0.5 times the pixels a side (each the mean of
# those it covers, the scale with them) and through JPEG at quality 80. The scene is the same
# in all of them: what moves is the pixels. Per record: the statuses (o ok, w warn, e error:
# the frame, then the draws, then mirror, quarter, 0.7, 0.5 and JPEG), which of them are right
# (R) or wrong (W) against truth.csv, the spread of
# μ over the draws against the edges' own σ (sigma_edges), and the range of μ; then a summary.
# A study, not a test: docs/photographs.md quotes it.
# usage: [KEEP=1] tests/photo/repeatability_study.sh BUILD_DIR [DRAWS] [DIR]
set -euo pipefail
build=$1
draws=${2:-8}
icacam=$build/host_tools/icacam
variants=$build/tests/photo/photo_frame_variants
src=$(cd "${3:-$(dirname "$0")/../data/photo}" && pwd)
tmp=$(mktemp -d)
# KEEP=1 keeps the variants and their records (the folder is printed).
if [ -n "${KEEP:-}" ]; then echo "variants in $tmp" >&2; else trap 'rm -rf "$tmp"' EXIT; fi

header=$(head -1 "$src/manifest.csv")
# The scale travels with the pixels: a frame of S times the pixels a side has 1/S the mm per px.
scaleCol=$(echo "$header" | tr -d '\r' | tr ',' '\n' | grep -nx mm_per_px | cut -d: -f1 || true)
resized=""
[ -n "$scaleCol" ] && resized="area70 area50"
sets="frame mirror quarter $resized jpeg80"
for k in $(seq 1 "$draws"); do sets="$sets noise$k"; done
for s in $sets; do
    mkdir -p "$tmp/$s/images"
    echo "$header" > "$tmp/$s/manifest.csv"
done
tail -n +2 "$src/manifest.csv" | while IFS=, read -r id image rest; do
    [ -n "$id" ] || continue
    echo "$id,$src/$image,$rest" >> "$tmp/frame/manifest.csv"
    for s in mirror quarter; do
        "$variants" "$src/$image" "$tmp/$s/images/$id.png" "$s"
        echo "$id,images/$id.png,$rest" >> "$tmp/$s/manifest.csv"
    done
    for s in $resized; do
        f=0.${s#area}
        "$variants" "$src/$image" "$tmp/$s/images/$id.png" area "$f"
        echo "$id,images/$id.png,$rest" |
            awk -F, -v c="$scaleCol" -v f="$f" 'BEGIN { OFS = "," } { $c = sprintf("%.7g", $c / f); print }' \
                >> "$tmp/$s/manifest.csv"
    done
    "$variants" "$src/$image" "$tmp/jpeg80/images/$id.png" jpeg 80
    echo "$id,images/$id.png,$rest" >> "$tmp/jpeg80/manifest.csv"
    seed=$(printf "%s" "$id" | cksum | cut -d' ' -f1)
    for k in $(seq 1 "$draws"); do
        "$variants" "$src/$image" "$tmp/noise$k/images/$id.png" noise $((seed + 7919 * k))
        echo "$id,images/$id.png,$rest" >> "$tmp/noise$k/manifest.csv"
    done
done
for s in $sets; do
    "$icacam" measure --manifest "$tmp/$s/manifest.csv" --out "$tmp/$s/r.csv" >/dev/null 2>&1 || true
done

python3 - "$tmp" "$src/truth.csv" "$draws" <<'EOF'
import csv, os, statistics, sys
tmp, truth_path, draws = sys.argv[1], sys.argv[2], int(sys.argv[3])
truth = {r['id']: r for r in csv.DictReader(open(truth_path))}
sets = ['frame'] + ['noise%d' % k for k in range(1, draws + 1)] + ['mirror', 'quarter']
sets += [s for s in ('area70', 'area50', 'jpeg80') if os.path.exists('%s/%s/r.csv' % (tmp, s))]
res = {s: {r['id']: r for r in csv.DictReader(open('%s/%s/r.csv' % (tmp, s)))} for s in sets}
flips = moved = silent_frame = silent_any = 0
ratios = []
print('%-20s %-14s %-14s %8s %10s  %s' % ('id', 'status', 'right', 'sd/sigma', 'sd(mu)', 'mu range (true)'))
for rid in sorted(res['frame']):
    rows = [res[s].get(rid) for s in sets]
    mu_true = float(truth[rid]['mu'])
    tol = max(0.01, 0.05 * mu_true)
    status = ''.join('e' if r is None or r['status'] == 'error' else r['status'][0] for r in rows)
    right = ''.join('-' if r is None or r['status'] == 'error'
                    else ('R' if abs(float(r['mu']) - mu_true) <= tol else 'W') for r in rows)
    noisy = [r for r in rows[1:draws + 1] if r is not None and r['status'] != 'error']
    mus = [float(r['mu']) for r in noisy]
    line = '%-20s %-14s %-14s' % (rid, status[0] + ' ' + status[1:draws + 1] + ' ' + status[draws + 1:],
                                   right[0] + ' ' + right[1:draws + 1] + ' ' + right[draws + 1:])
    if len(mus) >= 2:
        sd = statistics.stdev(mus)
        sigma = statistics.median(float(r['sigma_edges']) for r in noisy)
        ratios.append(sd / sigma)
        line += ' %8.2f %10.4f  %.4f..%.4f (%.4f)' % (sd / sigma, sd, min(mus), max(mus), mu_true)
        if sd > 0.5 * sigma:
            moved += 1
    print(line)
    if len(set(status)) > 1:
        flips += 1
    silent_frame += status[0] == 'o' and right[0] == 'W'
    silent_any += any(s == 'o' and r == 'W' for s, r in zip(status, right))
print('%d records; %d change status between the frame and its variants; %d move μ by more than half'
      ' their sigma_edges over the draws; median sd(μ)/sigma_edges %.2f; silent wrong: %d on the frame,'
      ' %d on any variant' % (len(res['frame']), flips, moved, statistics.median(ratios) if ratios else float('nan'),
                              silent_frame, silent_any))
EOF
