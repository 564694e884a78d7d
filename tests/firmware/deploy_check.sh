#!/usr/bin/env bash
# What deploy/ promises, checked without a board:
#   deploy_check.sh SOURCE_DIR path/to/icacam-fw
# the shipped config is one the program accepts and names /dev/serial0; the unit is
# Type=notify with a watchdog, runs in the operator group install.sh creates, and leaves the
# journal readable by that group only; its sandboxing scores as before (systemd-analyze, when
# there); install.sh passes shellcheck (when there). $ICACAM_EMULATOR runs a cross-built
# program (qemu).
set -euo pipefail
top=${1:?source dir}
fw=${2:?icacam-fw}
unit=$top/deploy/icacam-fw.service
conf=$top/deploy/device.conf
install=$top/deploy/install.sh
fail() {
    echo "deploy_check: $*" >&2
    exit 1
}

# shellcheck disable=SC2086 # the emulator is a command with arguments, or nothing
${ICACAM_EMULATOR:-} "$fw" --check --config "$conf" >/dev/null || fail "icacam-fw --check refuses deploy/device.conf"
grep -Eq '^device = /dev/serial0([[:space:]]|$)' "$conf" || fail "deploy/device.conf: serial device is not /dev/serial0"

for line in Type=notify NotifyAccess=main UMask=0027 StateDirectoryMode=0750 RuntimeDirectory=icacam; do
    grep -qx "$line" "$unit" || fail "the unit lacks $line"
done
grep -Eq '^WatchdogSec=[1-9][0-9]*$' "$unit" || fail "the unit has no WatchdogSec"
group=$(sed -n 's/^Group=//p' "$unit")
[ -n "$group" ] || fail "the unit has no Group="
grep -qx "operator_group=$group" "$install" || fail "install.sh does not create the unit's group $group"

if command -v systemd-analyze >/dev/null; then
    # 1.2 "OK" (docs/hardware.md); --threshold is the exposure times ten.
    systemd-analyze security --offline=true --threshold=15 "$unit" >/dev/null ||
        fail "the unit's exposure rose above 1.5 (systemd-analyze security --offline=true $unit)"
fi
if command -v shellcheck >/dev/null; then
    shellcheck "$install" || fail "shellcheck deploy/install.sh"
fi
echo "deploy_check: ok"
