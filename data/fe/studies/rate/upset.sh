#!/usr/bin/env bash
# The upsetting case with the rate-sensitive material (README.md, "The upsetting case"):
# *STATIC against *VISCO on the coarser-corner mesh (CAX8R h0.5 c0.1), one ccx at a time.
# The sweeps are resumable (cases already in a CSV are skipped); the summary is rewritten.
#   data/fe/studies/rate/upset.sh [path/to/icacam]      (from the repository root)
set -euo pipefail
icacam=${1:-build/host_tools/icacam}
dir=data/fe/studies/rate
setup=(--element CAX8R --corner 0.1 --elem 0.5 --inc-max 0.02 --reduction 0.6 --fallback-stick-slope 0
       --track-step 0.01 --work /tmp/icacam-fe-rate)
export OMP_NUM_THREADS=1
nice "$icacam" fe sweep --grid "k=500;n=0.25;mu=0.2,0.1" "${setup[@]}" --out $dir/upset_static.csv
nice "$icacam" fe sweep --grid "k=500;n=0.375;mu=0.2" "${setup[@]}" --out $dir/upset_static.csv
# Two press speeds a decade apart at m 0.05, then m 0, 0.05, 0.1 at 0.5 mm/s.
nice "$icacam" fe sweep --grid "k=500;n=0.25;mu=0.2;m=0.05;press-speed=0.5,5" "${setup[@]}" --out $dir/upset_visco.csv
nice "$icacam" fe sweep --grid "k=500;n=0.25;mu=0.2,0.1;press-speed=0.5;m=0,0.05,0.1" "${setup[@]}" \
    --out $dir/upset_visco.csv
# The speed decade at every m and both mu; a third (n, mu) point.
nice "$icacam" fe sweep --grid "k=500;n=0.25;mu=0.2,0.1;press-speed=5;m=0,0.05,0.1" "${setup[@]}" \
    --out $dir/upset_visco.csv
nice "$icacam" fe sweep --grid "k=500;n=0.375;mu=0.2;press-speed=0.5;m=0,0.05,0.1" "${setup[@]}" \
    --out $dir/upset_visco.csv
# The creep tolerance: CETOL 1e-3 against the default 1e-2, for the speed decade and the step in m.
nice "$icacam" fe sweep --grid "k=500;n=0.25;mu=0.2;m=0.05;press-speed=0.5,5;creep-tol=0.001" "${setup[@]}" \
    --out $dir/upset_visco.csv
nice "$icacam" fe sweep --grid "k=500;n=0.25;mu=0.2;m=0;press-speed=0.5;creep-tol=0.001" "${setup[@]}" \
    --out $dir/upset_visco.csv
$dir/upset.py --static $dir/upset_static.csv --visco $dir/upset_visco.csv --out $dir/upset_summary.csv \
    --md $dir/upset_summary.md --work /tmp/icacam-fe-rate
