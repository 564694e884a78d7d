#!/usr/bin/env bash
# A coarse sweep through the local executor and through a real single-node Slurm cluster
# (.ci/slurm-cluster): one job array, one task per case, and the same rows in the CSV.
source "$(dirname "$0")/fe_slurm_common.sh"
grid="n=0.1,0.4;mu=0.1,0.3"

"$icacam" fe sweep --grid "$grid" "${caseOptions[@]}" --work "$work/ccx-local" --out "$work/local.csv"
"$icacam" fe sweep --executor slurm --poll 1 --grid "$grid" "${caseOptions[@]}" --work "$work/ccx-slurm" \
    --out "$work/slurm.csv" | tee "$work/slurm.log"

fail() { echo "FAIL: $*"; exit 1; }
cases=$(cut -d, -f1 "$work/local.csv" | tail -n +2 | sort -u | wc -l)
[ "$cases" = 4 ] || fail "the local sweep has $cases cases, not 4"
jobs=("$work"/slurm.csv.slurm/jobs/*.cases)
[ "${#jobs[@]}" = 1 ] || fail "${#jobs[@]} submissions, not one job array"
[ "$(wc -l < "${jobs[0]}")" = 4 ] || fail "the job array has $(wc -l < "${jobs[0]}") tasks, not 4"
[ "$(ls "$work"/slurm.csv.slurm/results/*.csv | wc -l)" = 4 ] || fail "not one result file per case"
[ "$(head -1 "$work/local.csv")" = "$(head -1 "$work/slurm.csv")" ] || fail "headers differ"
if ! diff <(rowsWithoutWallTime "$work/local.csv") <(rowsWithoutWallTime "$work/slurm.csv"); then
    fail "the Slurm sweep's rows differ from the local executor's (above)"
fi
grep -q "RUNNING" "$work/slurm.log" || fail "no queue state (squeue) shown while waiting"

# Run again: every case has its rows, nothing is submitted.
before=$(md5sum < "$work/slurm.csv")
"$icacam" fe sweep --executor slurm --poll 1 --grid "$grid" "${caseOptions[@]}" --work "$work/ccx-slurm" \
    --out "$work/slurm.csv" | tee "$work/again.log"
[ "$(ls "$work"/slurm.csv.slurm/jobs/*.cases | wc -l)" = 1 ] || fail "a finished sweep submitted again"
[ "$(md5sum < "$work/slurm.csv")" = "$before" ] || fail "a finished sweep changed its CSV"
echo "PASS: $(wc -l < "$work/slurm.csv") lines, the same rows through Slurm as locally"
