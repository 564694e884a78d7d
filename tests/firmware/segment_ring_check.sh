#!/usr/bin/env bash
# icacam-fw as composed for a segmented LED ring, on the file HAL: the PC example's config
# (firmware/examples/segments.conf, its frames the committed rendered record with its four
# segment frames) with its paths moved into a temporary folder:
#   segment_ring_check.sh path/to/icacam-fw path/to/firmware/examples
# a scripted press lights each segment alone, then the whole ring; the result used the four
# segment frames, read the tilt, journaled them, and found segment 0 where the config says.
# $ICACAM_EMULATOR runs a cross-built program (qemu).
set -euo pipefail
fw=${1:?icacam-fw}
examples=$(cd "${2:?firmware/examples}" && pwd)
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
cd "$dir"
sed -e "s|^frames = .*|frames = $examples/segments.list|" -e "s|/tmp/icacam-fw/|$dir/|" \
    -e "s|^script = .*|script = presses.txt|" \
    "$examples/segments.conf" >device.conf
printf 'wait 200\npress 80\n' >presses.txt
mkdir -p display
fail() {
    echo "segment_ring_check: $*" >&2
    cat stderr.txt >&2 || true
    exit 1
}
# shellcheck disable=SC2086 # the emulator is a command with arguments, or nothing
${ICACAM_EMULATOR:-} "$fw" --check --config device.conf >check.txt 2>&1 || fail "config refused: $(cat check.txt)"
# shellcheck disable=SC2086
${ICACAM_EMULATOR:-} "$fw" --config device.conf 2>stderr.txt &
pid=$!
for _ in $(seq 1 300); do
    grep -q '"type":"result"' journal/journal.jsonl 2>/dev/null && break
    kill -0 "$pid" 2>/dev/null || break
    sleep 0.1
done
kill -TERM "$pid" 2>/dev/null || true
wait "$pid" || fail "icacam-fw did not stop cleanly"
result=$(grep '"type":"result"' journal/journal.jsonl) || fail "no measurement journaled"
for field in '"segment_frames":4' \
    '"segment_images":"img-000001-s0.pgm;img-000001-s1.pgm;img-000001-s2.pgm;img-000001-s3.pgm"' \
    '"segment_way":1' '"lit":"lit"'; do
    grep -qF "$field" <<<"$result" || fail "result lacks $field: $result"
done
grep -q '"tilt_knee_px":-\?[0-9]' <<<"$result" || fail "no tilt read: $result"
grep -q 'segment_problem' <<<"$result" && fail "a segment problem: $result"
for k in 0 1 2 3; do
    [ -s "journal/img-000001-s$k.pgm" ] || fail "segment frame $k not journaled"
done
grep -q ' segment 3$' led.log || fail "the LED log shows no segment lit alone: $(cat led.log)"
echo "segment_ring_check: ok"
