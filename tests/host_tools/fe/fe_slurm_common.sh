# Shared by the Slurm sweep tests (sourced): arguments, skips, the coarse CI-sized cases.
# usage: <test>.sh ICACAM SOURCE_DIR CLUSTER_DIR WORK_DIR
set -euo pipefail
icacam=$1
src=$2
cluster=$3
work=$4
if ! command -v ccx >/dev/null; then echo "skip: ccx (calculix-ccx) not installed"; exit 77; fi
if ! "$src/.ci/slurm-cluster" status "$cluster"; then
    echo "skip: no Slurm cluster in $cluster (.ci/slurm-cluster start could not start one here)"
    exit 77
fi
export SLURM_CONF=$cluster/slurm.conf
rm -rf "$work"
mkdir -p "$work"
# Coarse cases (uniform 0.5 mm CAX4R to 50 %: seconds each) with settings off their defaults,
# so a setting lost on the way to a Slurm task changes the rows.
caseOptions=(--elem 0.5 --reduction 0.5 --inc-max 0.02 --contact-slope 2e5 --timeout 170)

# The rows of a sweep CSV without wall_s (the solver's wall time, a measurement), sorted.
rowsWithoutWallTime() {
    local col
    col=$(head -1 "$1" | tr ',' '\n' | grep -nx wall_s | cut -d: -f1)
    [ -n "$col" ] || { echo "no wall_s column in $1" >&2; return 1; }
    cut -d, -f"1-$((col - 1)),$((col + 1))-" "$1" | sort
}
