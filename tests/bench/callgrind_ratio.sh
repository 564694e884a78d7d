#!/usr/bin/env bash
# Instructions per frame (callgrind) of our pipeline and of the plain OpenCV pipeline on the
# same frames, and their ratio. Per-frame = (I(repeat 6) − I(repeat 1)) / 5, so decoding and
# start-up cancel out.
#   --vision         count only inside EndFaceAnalyzer::measure (the vision pipeline of
#                    PRODUCT.md's speed goal); otherwise the whole `icacam measure` reading,
#                    the friction model's interpretation included
#   --min-ratio R    exit 1 when a frame's ratio is below R (the benchmark test)
# usage: tests/bench/callgrind_ratio.sh [--vision] [--min-ratio R] BUILD_DIR IMAGE N MM_PER_PX [IMAGE N MM_PER_PX ...]
set -euo pipefail
toggle=() minRatio=""
while [[ ${1:-} == --* ]]; do
    case $1 in
    --vision) toggle=(--collect-atstart=no '--toggle-collect=icacam::vision::EndFaceAnalyzer::measure(*') ;;
    --min-ratio) minRatio=$2; shift ;;
    *) echo "unknown option $1" >&2; exit 2 ;;
    esac
    shift
done
build=$1; shift
icacam=$build/host_tools/icacam
base=$build/tests/bench/cv_baseline
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
count() { # [callgrind options] -- command... → total instructions
    local opts=()
    while [ "$1" != -- ]; do opts+=("$1"); shift; done
    shift
    valgrind --tool=callgrind --callgrind-out-file="$tmp/cg.out" "${opts[@]}" "$@" >/dev/null 2>"$tmp/err" || {
        cat "$tmp/err" >&2; return 1; }
    grep -E '^summary:|^totals:' "$tmp/cg.out" | head -1 | awk '{print $2}'
}
status=0
printf "%-28s %14s %14s %8s\n" frame vision_instr opencv_instr ratio
while [ $# -ge 3 ]; do
    img=$1 n=$2 scale=$3; shift 3
    printf "id,image,n,mm_per_px\nb,%s,%s,%s\n" "$(realpath "$img")" "$n" "$scale" > "$tmp/m.csv"
    v1=$(count "${toggle[@]}" -- "$icacam" measure --manifest "$tmp/m.csv" --out "$tmp/o.csv" --repeat 1)
    v6=$(count "${toggle[@]}" -- "$icacam" measure --manifest "$tmp/m.csv" --out "$tmp/o.csv" --repeat 6)
    c1=$(count -- "$base" "$img" --repeat 1)
    c6=$(count -- "$base" "$img" --repeat 6)
    vf=$(( (v6 - v1) / 5 )); cf=$(( (c6 - c1) / 5 ))
    ratio=$(echo "$cf / $vf" | bc -l)
    printf "%-28s %14d %14d %8.1f\n" "$(basename "$img")" "$vf" "$cf" "$ratio"
    if [ -n "$minRatio" ] && [ "$(echo "$ratio < $minRatio" | bc -l)" = 1 ]; then
        echo "$(basename "$img"): ratio $(printf %.2f "$ratio") below $minRatio" >&2
        status=1
    fi
done
exit $status
