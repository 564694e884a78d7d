#!/usr/bin/env bash
# Instructions of the vision pipeline on every image of one or more manifests: callgrind
# counts only inside EndFaceAnalyzer::measure (--toggle-collect), one measurement per image,
# so the figure includes first-call costs (about 0.02–0.09 M more than the --repeat difference
# of callgrind_ratio.sh). Compare with the OpenCV pipeline's count on frames of the same size
# (callgrind_ratio.sh): 16.0–16.9 M at 1456×1088, 30.0–30.4 M at 2028×1520 on the devset.
# usage: tests/bench/callgrind_survey.sh BUILD_DIR MANIFEST [MANIFEST ...]  > table.txt
# prints: id width height instructions status
set -euo pipefail
build=$1; shift
icacam=$build/host_tools/icacam
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
for manifest in "$@"; do
    dir=$(cd "$(dirname "$manifest")" && pwd)
    header=$(head -1 "$manifest")
    tail -n +2 "$manifest" | while IFS= read -r line; do
        [ -n "$line" ] || continue
        id=${line%%,*}
        # The image path made absolute (column 2 by the data README's order).
        image=$(echo "$line" | cut -d, -f2)
        case $image in /*) path=$image ;; *) path=$dir/$image ;; esac
        printf "%s\n%s\n" "$header" "$(echo "$line" | sed "s#,$image,#,$path,#")" > "$tmp/m.csv"
        valgrind --tool=callgrind --callgrind-out-file="$tmp/cg.out" --collect-atstart=no \
            --toggle-collect='icacam::vision::EndFaceAnalyzer::measure(*' \
            "$icacam" measure --manifest "$tmp/m.csv" --model paper --out "$tmp/o.csv" >/dev/null 2>&1 || true
        ins=$(grep -E '^summary:|^totals:' "$tmp/cg.out" | head -1 | awk '{print $2}')
        size=$(python3 -c "
import struct,sys
b=open(sys.argv[1],'rb').read(1<<20)
if b[:8]==b'\x89PNG\r\n\x1a\n': print(*struct.unpack('>II',b[16:24])); sys.exit()
i=2
while i+9<len(b):
    if b[i]!=0xFF: i+=1; continue
    m=b[i+1]
    if m in (0xC0,0xC1,0xC2): h,w=struct.unpack('>HH',b[i+5:i+9]); print(w,h); sys.exit()
    if m==0xD8 or m==0x01 or 0xD0<=m<=0xD7: i+=2; continue
    i+=2+struct.unpack('>H',b[i+2:i+4])[0]
print('? ?')" "$path")
        status=$(tail -1 "$tmp/o.csv" | cut -d, -f2)
        echo "$id $size $ins $status"
    done
done
