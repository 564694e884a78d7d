#!/usr/bin/env bash
# Installs (or updates) icacam-fw on the board. Run as root on the board from a folder that
# holds icacam-fw (built natively or cross-built: docs/hardware.md) and this deploy/ folder.
#   sudo deploy/install.sh path/to/icacam-fw
# Idempotent: an update replaces the program and the unit and restarts the service; the
# config in /etc/icacam and the journal in /var/lib/icacam are kept.
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
fw=${1:?usage: install.sh path/to/icacam-fw}
file -b "$fw" | grep -q "ARM aarch64" || echo "install: warning: $fw is not an aarch64 program" >&2

for g in gpio i2c video dialout; do getent group "$g" >/dev/null || groupadd --system "$g"; done
id icacam >/dev/null 2>&1 || useradd --system --home-dir /var/lib/icacam --shell /usr/sbin/nologin icacam
usermod -a -G gpio,i2c,video,dialout icacam

install -m 0755 "$fw" /usr/local/bin/icacam-fw.new
mv /usr/local/bin/icacam-fw.new /usr/local/bin/icacam-fw # atomic replace of a running binary
install -m 0644 "$here/99-icacam.rules" /etc/udev/rules.d/99-icacam.rules
install -m 0644 "$here/icacam-fw.service" /etc/systemd/system/icacam-fw.service
install -d -m 0755 /etc/icacam
if [ ! -f /etc/icacam/device.conf ]; then
    install -m 0644 "$here/device.conf" /etc/icacam/device.conf
    echo "install: wrote /etc/icacam/device.conf: set specimen.n and calibration.mm_per_px"
fi
udevadm control --reload
udevadm trigger
/usr/local/bin/icacam-fw --config /etc/icacam/device.conf --check
systemctl daemon-reload
systemctl enable icacam-fw
systemctl restart icacam-fw
systemctl --no-pager status icacam-fw | head -5
