#!/usr/bin/env bash
# Cases the solver fails on come back through Slurm as rows with the solver's message, are
# listed at the end, and `--resubmit-failed 1` submits those cases again, alone.
source "$(dirname "$0")/fe_slurm_common.sh"
base=("$icacam" fe sweep --executor slurm --poll 1 "${caseOptions[@]}" --fallback-stick-slope 0 --work "$work/ccx"
      --out "$work/sweep.csv")
fail() { echo "FAIL: $*"; exit 1; }

# One case solved; the grid extended by a case that fails: the solver is not where --ccx says
# (as on a node without the set-up line). The solved case is not touched again.
"${base[@]}" --grid "elem=2"
"${base[@]}" --grid "elem=2,1" --ccx "$work/no-such-ccx" | tee "$work/first.log"
failed=$(grep '^failed: ' "$work/first.log" | cut -d' ' -f2 | tr -d : | sort)
ok=$(tail -n +2 "$work/sweep.csv" | awk -F, '$2 == "ok" { print $1 }' | sort -u)
[ "$(echo "$failed" | grep -c .)" = 1 ] || fail "not one failed case listed"
[ "$(echo "$ok" | grep -c .)" = 1 ] || fail "not one solved case"
message=$(tail -n +2 "$work/sweep.csv" | awk -F, '$2 != "ok"' | head -1 | cut -d, -f29)
[ -n "$message" ] || fail "the failed case's rows say nothing about why"
grep -qF "failed: $failed: error: $message" "$work/first.log" || fail "the solver's message ($message) is not listed"
[ "$(tail -n +2 "$work/sweep.csv" | awk -F, '$2 != "ok" { print $1 }' | sort -u)" = "$failed" ] ||
    fail "the listed failures are not the CSV's"

"${base[@]}" --grid "elem=2,1" --resubmit-failed 1 | tee "$work/second.log"
subs=$(ls "$work"/sweep.csv.slurm/jobs/*.cases | sort -V)
[ "$(echo "$subs" | wc -l)" = 3 ] || fail "not one new submission for the failed case"
[ "$(awk -F'\t' '{ print $2 }' "$(echo "$subs" | tail -1)" | sort)" = "$failed" ] ||
    fail "the resubmission is not exactly the failed case"
[ -z "$(tail -n +2 "$work/sweep.csv" | awk -F, '$2 != "ok"')" ] || fail "a case is still failed"
[ "$(cut -d, -f1 "$work/sweep.csv" | tail -n +2 | sort -u | wc -l)" = 2 ] || fail "not 2 cases in the CSV"
[ "$(tail -n +2 "$work/sweep.csv" | awk -F, '{ print $1 }' | sort | uniq -c | awk '{ print $1 }' | sort -u)" = 10 ] ||
    fail "not 10 rows per case (the failed rows were not replaced)"

# A task that ends without rows (here cancelled while it runs; on a cluster a time limit, a
# lost node) is listed with its Slurm state, the sweep exits 1, and the next run submits it.
# Its solver runs until it is stopped: a real one-element case can finish before --cancel
# comes on a loaded machine, and the test would then judge the machine's speed.
printf '#!/bin/sh\nexec sleep 600\n' > "$work/ccx-until-stopped"
chmod +x "$work/ccx-until-stopped"
lost=("$icacam" fe sweep --executor slurm --poll 1 --grid "mu=0.3" "${caseOptions[@]}" --work "$work/ccx"
      --ccx "$work/ccx-until-stopped" --out "$work/lost.csv")
"${lost[@]}" > "$work/lost.log" 2>&1 &
pid=$!
name=""
for _ in $(seq 1 120); do
    name=$(grep -o 'icacam-fe-[0-9a-f]*' "$work/lost.log" | head -1 || true)
    [ -n "$name" ] && [ -n "$(squeue -h -t RUNNING -n "$name" -o %i)" ] && break
    sleep 0.5
done
[ -n "$name" ] || fail "the sweep never showed a running task"
# A second command on the same sweep would gather the same results twice: refused.
if "${lost[@]}" > "$work/second-watcher.log" 2>&1; then fail "a second sweep command watched the same directory"; fi
grep -q "another sweep command watches" "$work/second-watcher.log" || { cat "$work/second-watcher.log"; fail "no reason given"; }
# --cancel from another command while the sweep waits (a lab member stopping a sweep).
"$icacam" fe sweep --executor slurm --out "$work/lost.csv" --cancel 1 | tee "$work/cancel.log"
grep -q "cancelled 1 tasks" "$work/cancel.log" || fail "--cancel did not cancel the running task"
rc=0
wait "$pid" || rc=$?
cat "$work/lost.log"
[ "$rc" = 1 ] || fail "a sweep with a case left without rows exited $rc, not 1"
grep -q "no result: task .* ended CANCELLED" "$work/lost.log" || fail "the task's end (CANCELLED) is not listed"
[ ! -s "$work/lost.csv" ] || [ "$(tail -n +2 "$work/lost.csv" | wc -l)" = 0 ] || fail "rows for a cancelled case"
"$icacam" fe sweep --executor slurm --out "$work/lost.csv" --cancel 1 | grep -q "cancelled 0 tasks" ||
    fail "--cancel found tasks of a finished sweep"
echo "PASS: $(echo "$failed" | wc -l) failed case(s) listed and resubmitted alone; a cancelled task listed; a second watcher refused"
