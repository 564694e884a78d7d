#!/usr/bin/env bash
# icacam-fw comes up without its display and its serial line, as on a fresh Raspberry Pi OS
# with I2C and the UART off:
#   missing_parts_check.sh path/to/icacam-fw
# it keeps running (no exit for systemd to restart), names both parts on stderr (journalctl)
# and in the journal, measures a scripted press and journals it. A build without the ssd1306
# and termios backends cannot be asked for them: skipped (77). $ICACAM_EMULATOR runs a
# cross-built program (qemu).
set -euo pipefail
fw=${1:?icacam-fw}
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
cd "$dir"
mkdir frames
{
    printf 'P5\n64 64\n255\n'
    head -c 4096 /dev/zero | tr '\0' '\170'
} >frames/a.pgm
cat >device.conf <<'CONF'
[specimen]
n = 0.2
[calibration]
mm_per_px = 0.0125
[camera]
frames = frames
loop = 1
max_width = 256
max_height = 256
[trigger]
script = presses.txt
[display]
backend = ssd1306
i2c_bus = 250
[serial]
backend = uart
device = /dev/icacam-no-such-serial0
[journal]
dir = journal
CONF
printf 'wait 200\npress 80\n' >presses.txt
fail() {
    echo "missing_parts_check: $*" >&2
    cat stderr.txt >&2 || true
    exit 1
}

# shellcheck disable=SC2086 # the emulator is a command with arguments, or nothing
if ! ${ICACAM_EMULATOR:-} "$fw" --check --config device.conf >check.txt 2>&1; then
    grep -q "backend only" check.txt && exit 77
    fail "icacam-fw --check refuses the config: $(cat check.txt)"
fi
# shellcheck disable=SC2086
${ICACAM_EMULATOR:-} "$fw" --config device.conf 2>stderr.txt &
pid=$!
for _ in $(seq 1 100); do
    grep -q '"type":"result"' journal/journal.jsonl 2>/dev/null && break
    kill -0 "$pid" 2>/dev/null || break
    sleep 0.1
done
kill -0 "$pid" 2>/dev/null || {
    wait "$pid" && rc=0 || rc=$?
    fail "icacam-fw stopped (exit $rc) with a part missing"
}
kill -TERM "$pid"
wait "$pid" || fail "icacam-fw did not stop cleanly on SIGTERM"
grep -q 'display missing: /dev/i2c-250' stderr.txt || fail "stderr does not name the missing display"
grep -q 'serial missing: serial /dev/icacam-no-such-serial0' stderr.txt || fail "stderr does not name the missing serial line"
grep -q '"type":"part","id":0,"part":"display","state":"missing"' journal/journal.jsonl || fail "journal: no display event"
grep -q '"type":"part","id":0,"part":"serial","state":"missing"' journal/journal.jsonl || fail "journal: no serial event"
grep -q '"type":"result","id":1' journal/journal.jsonl || fail "no measurement journaled"
echo "missing_parts_check: ok"
