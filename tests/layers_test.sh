#!/usr/bin/env bash
# .ci/check-layers passes on the tree and fails on each kind of wrong arrow: a vision header
# including reading, hal linking vision, host_tools/fe including host_tools/loop.
set -euo pipefail
root=$1
check=$root/.ci/check-layers
bash "$check" "$root" >/dev/null || { echo "check-layers fails on the tree itself"; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fails() { # $1: what was broken
    if bash "$check" "$work/t" >/dev/null; then echo "check-layers passed with $1"; exit 1; fi
}
fresh() { rm -rf "$work/t" && mkdir "$work/t" && cp -r "$root"/{friction,vision,reading,calibration,hal,firmware,host_tools} "$work/t/"; }
fresh
echo '#include "reading/reading.h"' >>"$work/t/vision/luma_view.h"
fails "vision including reading"
fresh
echo 'target_link_libraries(icacam_hal INTERFACE icacam_vision)' >>"$work/t/hal/CMakeLists.txt"
fails "hal linking vision"
fresh
echo '#include "host_tools/loop/loop_analysis.h"' >>"$work/t/host_tools/fe/fe_tables.cpp"
fails "fe including loop"
fresh
echo 'target_link_libraries(icacam_friction PUBLIC icacam_vision)' >>"$work/t/friction/CMakeLists.txt"
fails "friction linking vision"
echo "check-layers: passes on the tree, fails on each wrong arrow"
