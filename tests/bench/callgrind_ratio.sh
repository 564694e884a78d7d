#!/usr/bin/env bash
# Instructions per frame (callgrind) of the vision pipeline and of the plain OpenCV pipeline
# on the same frames, and their ratio. Per-frame = (I(repeat 6) − I(repeat 1)) / 5, so
# decoding and start-up cancel out.
# usage: tests/bench/callgrind_ratio.sh BUILD_DIR IMAGE N MM_PER_PX [IMAGE N MM_PER_PX ...]
set -euo pipefail
build=$1; shift
icacam=$build/host_tools/icacam
base=$build/tests/bench/cv_baseline
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
count() { # command... → total instructions
    valgrind --tool=callgrind --callgrind-out-file="$tmp/cg.out" "$@" >/dev/null 2>"$tmp/err" || {
        cat "$tmp/err" >&2; return 1; }
    grep -E '^summary:|^totals:' "$tmp/cg.out" | head -1 | awk '{print $2}'
}
printf "%-28s %14s %14s %8s\n" frame vision_instr opencv_instr ratio
while [ $# -ge 3 ]; do
    img=$1 n=$2 scale=$3; shift 3
    printf "id,image,n,mm_per_px\nb,%s,%s,%s\n" "$(realpath "$img")" "$n" "$scale" > "$tmp/m.csv"
    v1=$(count "$icacam" measure --manifest "$tmp/m.csv" --out "$tmp/o.csv" --repeat 1)
    v6=$(count "$icacam" measure --manifest "$tmp/m.csv" --out "$tmp/o.csv" --repeat 6)
    c1=$(count "$base" "$img" --repeat 1)
    c6=$(count "$base" "$img" --repeat 6)
    vf=$(( (v6 - v1) / 5 )); cf=$(( (c6 - c1) / 5 ))
    printf "%-28s %14d %14d %8.1f\n" "$(basename "$img")" "$vf" "$cf" "$(echo "$cf / $vf" | bc -l)"
done
