#!/usr/bin/env bash
# Writes every study page here from the committed CSVs in data/fe/ (no CalculiX needed): the
# `icacam fe compare` pages and `icacam fe report`'s comparison with the paper and its two
# plots. Each page's first line names its command. Run from the repository root after a build:
#   data/fe/studies/regenerate.sh [ICACAM]   (default build/host_tools/icacam)
set -euo pipefail
icacam=${1:-build/host_tools/icacam}
cd "$(dirname "$0")/../../.."
d=data/fe
out=data/fe/studies
compare() { "$icacam" fe compare --edge track "$@" >/dev/null; }

compare --in $d/sweep_cax8r_c005_st1e5_tracked.csv --in $d/mesh_study_c0025_st1e5_tracked.csv --bar 0.01 --out $out/mesh_study_st1e5.md
compare --in $d/mesh_study_c0025_tracked.csv --in $d/mesh_study_c00125_tracked.csv --bar 0.01 --out $out/mesh_study_c00125.md
compare --in $d/sweep_cax8r_c005_tracked.csv --in $d/mesh_study_c0025_tracked.csv --bar 0.01 --out $out/mesh_study.md
compare --in $d/sweep_cax8r_c005_st1e5_tracked.csv --in $d/mesh_study_farfield_st1e5_tracked.csv --bar 0.01 --out $out/mesh_study_farfield_st1e5.md
compare --in $d/sweep_cax8r_c005_tracked.csv --in $d/sweep_cax8r_tracked.csv --bar 0.01 --out $out/mesh_coarse.md
compare --in $d/sweep_cax8r_c005_tracked.csv --in $d/sweep_cax8r_c005_st1e5_tracked.csv --bar 0.01 --out $out/stick_slope.md
compare --in $d/sweep_cax8r_tracked.csv --in $d/penalty_study_cax8r_tracked.csv --bar 0.01 --out $out/penalty_study.md
compare --in $d/independent_cax4r_refined.csv --in $d/stick_slope_tracked.csv --bar 0.01 --out $out/stick_slope_cax4r.md
compare --in $d/sweep_cax8r_tracked.csv --in $d/factorial_k_cax8r_tracked.csv --across-material 1 --out $out/factorial.md
compare --in $d/sweep_cax8r_tracked.csv --in $d/checks_cax8r_tracked.csv --across-material 1 --out $out/checks.md
compare --in $d/sweep_cax8r_c005_st1e5_tracked.csv --in $d/independent_foldzone_st1e5.csv \
    --in $d/independent_foldzone_st1e5_lowmu.csv --out $out/independent_st1e5.md
compare --in $d/sweep_cax8r_c005_st1e5_tracked.csv --in $d/independent_cax4r_refined.csv \
    --in $d/independent_cax4r_farfield.csv --out $out/independent_cax4r_farfield.md
compare --in $d/sweep_cax8r_c005_tracked.csv --in $d/independent_cax4r_tracked.csv --in $d/independent_cax4r_refined.csv \
    --in $d/independent_foldzone.csv --out $out/independent.md
"$icacam" fe report --in $d/sweep_cax8r_c005_st1e5_tracked.csv --in $d/sweep_cax8r_c005_tracked.csv \
    --in $d/sweep_cax8r_tracked.csv --in $d/factorial_k_cax8r_tracked.csv --out $out >/dev/null
