#!/usr/bin/env bash
# The per-condition coverage table of docs/uncertainty.md: renders COUNT records of every
# condition (seeded), measures them with `icacam measure` (default model) and scores them.
#   tests/host_tools/coverage_table.sh [BUILD_DIR] [OUT_DIR] [COUNT] [SEED]
set -euo pipefail
build=${1:-build}
out=${2:-/tmp/icacam-coverage}
count=${3:-40}
seed=${4:-16}
icacam="$build/host_tools/icacam"
rm -rf "$out"
"$icacam" synth --out "$out" --condition all --count "$count" --seed "$seed" >"$out.synth.log" 2>&1 ||
    { cat "$out.synth.log"; exit 1; }
"$icacam" measure --manifest "$out/manifest.csv" --out "$out/results.csv"
"$icacam" score --results "$out/results.csv" --truth "$out/truth.csv" --markdown
