#!/usr/bin/env bash
# Kill the Slurm sweep command while its tasks run, lose one task on the cluster (scancel),
# start the command again: it gathers what finished, waits for the tasks still queued and
# submits only the cases that have neither a result nor a task.
source "$(dirname "$0")/fe_slurm_common.sh"
grid="n=0.1,0.25,0.4;mu=0.1,0.3"
# Two tasks at a time whatever the node's CPUs: there are queued tasks when the first lands.
sweep=("$icacam" fe sweep --executor slurm --poll 1 --array-limit 2 --grid "$grid" "${caseOptions[@]}" --work "$work/ccx"
       --out "$work/sweep.csv")
results=$work/sweep.csv.slurm/results
fail() { echo "FAIL: $*"; exit 1; }

"${sweep[@]}" > "$work/first.log" 2>&1 &
pid=$!
for _ in $(seq 1 240); do
    ls "$results"/*.csv >/dev/null 2>&1 && break
    kill -0 "$pid" 2>/dev/null || { cat "$work/first.log"; fail "the sweep ended before any result"; }
    sleep 0.5
done
kill -KILL "$pid"
wait "$pid" 2>/dev/null || true
cat "$work/first.log"
name=$(grep -o 'icacam-fe-[0-9a-f]*' "$work/first.log" | head -1)
[ -n "$name" ] || fail "no job name in the first run's output"
queued=$(squeue -h -r -n "$name" -o "%F_%K")
[ -n "$queued" ] || fail "no task left in the queue when the sweep was killed: the cases ran too fast to test this"
# One task lost on the cluster (preempted, a node gone): its case has no result and no task.
# A pending one: a running one may finish before scancel reaches it.
lost=$(squeue -h -r -t PENDING -n "$name" -o "%F_%K" | sort -t_ -k2 -n | tail -1)
[ -n "$lost" ] || fail "no pending task when the sweep was killed: the cases ran too fast to test this"
scancel "$lost"
for _ in $(seq 1 50); do
    squeue -h -r -n "$name" -o "%F_%K" | grep -qx "$lost" || break
    sleep 0.2
done
# The cases with a task in the queue (first), then those with a result.
declare -A mapped
while IFS=$'\t' read -r index label; do mapped[${index}]=$label; done < "$(ls "$work"/sweep.csv.slurm/jobs/*.cases)"
live=""
for t in $(squeue -h -r -n "$name" -o "%K"); do live="$live ${mapped[$t]}"; done
solved=$(cd "$results" && ls *.csv 2>/dev/null | sed 's/\.csv$//')
all=$(awk -F'\t' '{ print $2 }' "$work"/sweep.csv.slurm/jobs/*.cases | sort)
expected=$(comm -23 <(echo "$all") <(printf '%s\n' $live $solved | sort -u))
echo "killed with results: $(echo $solved | wc -w), queued: $(echo $live | wc -w), lost: $lost"
[ -n "$expected" ] || fail "nothing to resubmit: the lost task's case has a result"

"${sweep[@]}" | tee "$work/second.log"

subs=$(ls "$work"/sweep.csv.slurm/jobs/*.cases | sort -V)
[ "$(echo "$subs" | wc -l)" = 2 ] || fail "$(echo "$subs" | wc -l) submissions, not 2"
resubmitted=$(awk -F'\t' '{ print $2 }' "$(echo "$subs" | tail -1)" | sort)
if [ "$resubmitted" != "$expected" ]; then
    echo "resubmitted:"; echo "$resubmitted"; echo "expected (no result, no task):"; echo "$expected"
    fail "the restart resubmitted other cases than those without a result"
fi
# Every case once in the CSV, solved.
[ "$(cut -d, -f1 "$work/sweep.csv" | tail -n +2 | sort -u | wc -l)" = 6 ] || fail "not 6 cases in the CSV"
[ "$(tail -n +2 "$work/sweep.csv" | wc -l)" = 60 ] || fail "not 10 rows per case (a case gathered twice or partly)"
[ -z "$(tail -n +2 "$work/sweep.csv" | cut -d, -f2 | grep -vx ok)" ] || fail "a case did not solve"
echo "PASS: the restart resubmitted $(echo "$resubmitted" | wc -l) case(s), those without a result or a task"
