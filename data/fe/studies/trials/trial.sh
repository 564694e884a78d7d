#!/bin/bash
# One convergence trial (data/fe/convergence_trials.csv): the deck `icacam fe deck ARGS` writes,
# optionally edited by one of the Python scripts here (environment variables select the
# variant, see each script), run by ccx in ./NAME; prints the wall time and the last .sta line.
# usage: ICACAM=build/host_tools/icacam data/fe/studies/trials/trial.sh NAME "deck args" [edit.py]
set -u
here=$(cd "$(dirname "$0")" && pwd)
icacam=$(realpath "${ICACAM:-build/host_tools/icacam}")
name=$1; args=$2; edit=${3:-}
mkdir -p "$name" && cd "$name"
$icacam fe deck $args > job.inp
if [ -n "$edit" ]; then python3 "$here/$edit" job.inp; fi
start=$(date +%s.%N)
OMP_NUM_THREADS=1 CCX_NPROC_EQUATION_SOLVER=1 timeout 1800 nice -n 5 ccx -i job > ccx.log 2>&1
end=$(date +%s.%N)
echo "$name wall $(echo "$end - $start" | bc) s; last: $(tail -1 job.sta)"
grep -m1 -E "ERROR|Job finished" ccx.log
