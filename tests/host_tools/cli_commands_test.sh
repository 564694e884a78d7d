#!/usr/bin/env bash
# Every command line of `icacam` and `icacam-fw`: --help prints the usage and exits 0; a bad
# option names itself, prints the usage and exits 2 (icacam-fw: 64, its systemd contract);
# `icacam fe --preset base` is the setup of the models' FE base: a sweep with it over the base's
# (n, μ) finds every case already in the base and its deck is the deck of the base's own
# settings; the defaults (the coarse first-sweep setup) are those the help states.
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
expect 2 "missing: --manifest" "$icacam" measure --out x.csv
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
base=$(grep -o 'kBase = "[^"]*"' "$src/friction/fe_model_table.h" | cut -d'"' -f2)
[ -f "$src/$base" ] || fail "no base file $base"
column() { # the distinct values of a column of the base, comma-separated
    local col
    col=$(head -1 "$src/$base" | tr ',' '\n' | grep -nx "$1" | cut -d: -f1)
    tail -n +2 "$src/$base" | cut -d, -f"$col" | sort -u -g | paste -sd,
}
cp "$src/$base" "$work/base.csv"
# A solver that cannot run: a case the defaults do not match fails at once instead of running.
"$icacam" fe sweep --preset base --grid "k=$(column k_mpa);n=$(column n);mu=$(column mu)" --out "$work/base.csv" \
    --ccx "$work/no-ccx" --work "$work/ccx" >"$work/sweep.log"
cases=$(tail -n +2 "$src/$base" | cut -d, -f1 | sort -u | wc -l)
grep -q "sweep: $cases cases, $cases already in" "$work/sweep.log" ||
    fail "a --preset base sweep over the base's grid does not find its $cases cases: $(cat "$work/sweep.log")"
cmp -s "$work/base.csv" "$src/$base" || fail "the --preset base sweep changed the base's rows"
for setting in element corner_mm elem_mm stick_slope contact_slope inc_max reduction_max track_step; do
    [ "$(column $setting | tr -cd , | wc -c)" = 0 ] || fail "the base mixes $setting values"
done
"$icacam" fe deck --n 0.25 --mu 0.2 --preset base >"$work/preset.inp"
"$icacam" fe deck --n 0.25 --mu 0.2 --element "$(column element)" --corner "$(column corner_mm)" \
    --elem "$(column elem_mm)" --stick-slope "$(column stick_slope)" --contact-slope "$(column contact_slope)" \
    --inc-max "$(column inc_max)" --reduction "$(column reduction_max)" --track-step "$(column track_step)" \
    >"$work/base.inp"
cmp -s "$work/preset.inp" "$work/base.inp" || fail "the --preset base deck is not the base's"
# Options beside the preset win, wherever they stand.
"$icacam" fe deck --corner 0.1 --preset=base >"$work/corner.inp"
"$icacam" fe deck --preset base --corner 0.1 >"$work/corner2.inp"
cmp -s "$work/corner.inp" "$work/corner2.inp" && ! cmp -s "$work/corner.inp" "$work/preset.inp" ||
    fail "an option beside --preset base does not win"
# The defaults the help states are the defaults: the deck with them spelled out is the default deck.
"$icacam" fe --help >"$work/fe-help"
stated=$(sed -n '/^case options, with their defaults/,/^  --preset/p' "$work/fe-help" | grep -o -- '--[a-z0-9-]* [^ (]*' |
         grep -v -- '--preset')
[ "$(echo "$stated" | wc -l)" -ge 15 ] || fail "fe --help states only $(echo "$stated" | wc -l) case defaults"
"$icacam" fe deck >"$work/default.inp"
# shellcheck disable=SC2046
"$icacam" fe deck $(echo "$stated" | tr '\n' ' ') >"$work/stated.inp"
cmp -s "$work/default.inp" "$work/stated.inp" || fail "the deck of the defaults fe --help states is not the default deck"
! cmp -s "$work/default.inp" "$work/preset.inp" || fail "--preset base changed nothing"
echo "PASS: every command's --help and bad option; fe's stated defaults; --preset base reproduces $base ($cases cases)"
