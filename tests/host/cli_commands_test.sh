#!/usr/bin/env bash
# Every command line of `icacam` and `icacam-fw`: --help prints the usage and exits 0; a bad
# option names itself, prints the usage and exits 2 (icacam-fw: 64, its systemd contract);
# `icacam fe`'s defaults are the setup of the models' FE base: without case options a sweep
# over the base's (n, μ) finds every case already in the base and the default deck is the
# deck of the base's own settings.
# usage: cli_commands_test.sh ICACAM ICACAM_FW SOURCE_DIR WORK_DIR
set -euo pipefail
icacam=$1 fw=$2 src=$3 work=$4
rm -rf "$work" && mkdir -p "$work"
fail() { echo "FAIL: $*"; exit 1; }

expect() { # expect RC WHAT COMMAND... : the exit code and, on stderr or stdout, WHAT
    local rc=0 want=$1 what=$2
    shift 2
    "$@" >"$work/out" 2>"$work/err" || rc=$?
    [ "$rc" = "$want" ] || fail "'$*' exited $rc, not $want: $(cat "$work/err")"
    grep -qF -- "$what" "$work/out" "$work/err" || fail "'$*' does not say '$what'"
    grep -q "^usage: " "$work/out" "$work/err" || fail "'$*' prints no usage"
}

for c in measure synth score calibrate loop ctl "fe" "fe deck" "fe run" "fe sweep" "fe report" "fe compare" "fe tables"; do
    # shellcheck disable=SC2086
    expect 0 "usage: icacam ${c%% *}" "$icacam" $c --help
    # shellcheck disable=SC2086
    expect 2 "'--no-such-option'" "$icacam" $c --no-such-option
done
expect 2 "--manifest needs a value" "$icacam" measure --manifest
expect 2 "--count: a whole number" "$icacam" synth --out "$work/s" --count=many
expect 2 "--model: unknown model 'nope'" "$icacam" loop --manifest m.csv --report r --model nope
expect 2 "fe tables" "$icacam" loop table
expect 2 "a command is needed" "$icacam"
expect 0 "usage: icacam-fw" "$fw" --help
expect 64 "unknown option '--no-such-option'" "$fw" --no-such-option
expect 64 "--config needs a value" "$fw" --config

# --name=value reads as --name value.
"$icacam" synth --out="$work/a" --count=2 --seed=3 2>/dev/null
"$icacam" synth --out "$work/b" --count 2 --seed 3 2>/dev/null
cmp -s "$work/a/truth.csv" "$work/b/truth.csv" || fail "--name=value and --name value made different sets"

# The FE defaults against the base the models' tables were made from.
base=$(grep -o 'kBase = "[^"]*"' "$src/vision/model/fe_model_table.h" | cut -d'"' -f2)
[ -f "$src/$base" ] || fail "no base file $base"
column() { # the distinct values of a column of the base, comma-separated
    local col
    col=$(head -1 "$src/$base" | tr ',' '\n' | grep -nx "$1" | cut -d: -f1)
    tail -n +2 "$src/$base" | cut -d, -f"$col" | sort -u -g | paste -sd,
}
cp "$src/$base" "$work/base.csv"
# A solver that cannot run: a case the defaults do not match fails at once instead of running.
"$icacam" fe sweep --grid "k=$(column k_mpa);n=$(column n);mu=$(column mu)" --out "$work/base.csv" \
    --ccx "$work/no-ccx" --work "$work/ccx" >"$work/sweep.log"
cases=$(tail -n +2 "$src/$base" | cut -d, -f1 | sort -u | wc -l)
grep -q "sweep: $cases cases, $cases already in" "$work/sweep.log" ||
    fail "a default sweep over the base's grid does not find its $cases cases: $(cat "$work/sweep.log")"
cmp -s "$work/base.csv" "$src/$base" || fail "the default sweep changed the base's rows"
for setting in element corner_mm elem_mm stick_slope contact_slope inc_max reduction_max track_step; do
    [ "$(column $setting | tr -cd , | wc -c)" = 0 ] || fail "the base mixes $setting values"
done
"$icacam" fe deck --n 0.25 --mu 0.2 >"$work/default.inp"
"$icacam" fe deck --n 0.25 --mu 0.2 --element "$(column element)" --corner "$(column corner_mm)" \
    --elem "$(column elem_mm)" --stick-slope "$(column stick_slope)" --contact-slope "$(column contact_slope)" \
    --inc-max "$(column inc_max)" --reduction "$(column reduction_max)" --track-step "$(column track_step)" \
    >"$work/base.inp"
cmp -s "$work/default.inp" "$work/base.inp" || fail "the default deck is not the base's"
"$icacam" fe --help >"$work/fe-help"
for stated in "--element $(column element)" "--corner $(column corner_mm)" "--stick-slope $(column stick_slope)" "--reduction $(column reduction_max)"; do
    grep -qF -- "$stated" "$work/fe-help" || fail "fe --help does not state the default $stated"
done
echo "PASS: every command's --help and bad option; the FE defaults reproduce $base ($cases cases)"
