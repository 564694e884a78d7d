#!/usr/bin/env bash
# Installs (or updates) icacam-fw on the board. Run as root on the board from a folder that
# holds icacam-fw (built natively or cross-built: docs/hardware.md) and this deploy/ folder.
#   sudo deploy/install.sh path/to/icacam-fw
# Idempotent: an update replaces the program and the unit and restarts the service; the
# config in /etc/icacam and the journal in /var/lib/icacam are kept.
#
# Operators: the service writes its journal, frames and snapshots group-readable for the
# group icacam-operators (the unit's Group=, StateDirectoryMode=0750, UMask=0027), so a
# person in that group can read and copy them (`scp pi@board:/var/lib/icacam/journal/snap-*.png .`)
# without root. The user who ran sudo is added to it, and the users named in
# ICACAM_OPERATORS (space-separated); they log in again for the group to take effect.
#   sudo ICACAM_OPERATORS="alice bob" deploy/install.sh icacam-fw
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
fw=${1:?usage: install.sh path/to/icacam-fw}
operator_group=icacam-operators
file -b "$fw" | grep -q "ARM aarch64" || echo "install: warning: $fw is not an aarch64 program" >&2

for g in gpio i2c video dialout; do getent group "$g" >/dev/null || groupadd --system "$g"; done
getent group "$operator_group" >/dev/null || groupadd --system "$operator_group"
id icacam >/dev/null 2>&1 || useradd --system --home-dir /var/lib/icacam --shell /usr/sbin/nologin icacam
usermod -a -G gpio,i2c,video,dialout,"$operator_group" icacam
for u in ${SUDO_USER:-} ${ICACAM_OPERATORS:-}; do
    [ "$u" = root ] && continue
    if id "$u" >/dev/null 2>&1; then
        usermod -a -G "$operator_group" "$u"
        echo "install: $u is in $operator_group (reads /var/lib/icacam; log in again to use it)"
    else
        echo "install: warning: no user $u to add to $operator_group" >&2
    fi
done

install -m 0755 "$fw" /usr/local/bin/icacam-fw.new
mv /usr/local/bin/icacam-fw.new /usr/local/bin/icacam-fw # atomic replace of a running binary
install -m 0644 "$here/99-icacam.rules" /etc/udev/rules.d/99-icacam.rules
install -m 0644 "$here/icacam-fw.service" /etc/systemd/system/icacam-fw.service
install -d -m 0755 /etc/icacam
if [ ! -f /etc/icacam/device.conf ]; then
    install -m 0644 "$here/device.conf" /etc/icacam/device.conf
    echo "install: wrote /etc/icacam/device.conf: set specimen.n and calibration.mm_per_px"
fi
# A journal written before the operator group existed: systemd hands the state folder to
# the unit's user and group on start; the modes are set here once.
if [ -d /var/lib/icacam ]; then
    chgrp -R "$operator_group" /var/lib/icacam
    chmod -R g+rX,g-w,o-rwx /var/lib/icacam
fi

# What a fresh Raspberry Pi OS lacks (docs/hardware.md, first power-up): said, not changed;
# each takes a reboot.
serial=$(awk -F= '
    /^[[:space:]]*\[/ { section = $0; gsub(/[][[:space:]]/, "", section); next }
    { key = $1; gsub(/[[:space:]]/, "", key); value = $2; sub(/#.*/, "", value); gsub(/[[:space:]"]/, "", value)
      if ((section == "serial" && key == "device") || key == "serial.device") print value }' /etc/icacam/device.conf | tail -1)
if [ ! -e /dev/i2c-1 ]; then
    echo "install: no /dev/i2c-1 (display): sudo raspi-config nonint do_i2c 0, then reboot" >&2
fi
if [ -n "$serial" ] && [ ! -e "$serial" ]; then
    echo "install: no $serial (serial line): sudo raspi-config nonint do_serial_hw 0 &&" \
        "sudo raspi-config nonint do_serial_cons 1, then reboot; on a Pi 5 also dtparam=uart0_console" \
        "in /boot/firmware/config.txt for /dev/serial0 (docs/hardware.md)" >&2
elif [ -n "$serial" ]; then
    echo "install: $serial is $(readlink -f "$serial")"
fi

udevadm control --reload
udevadm trigger
/usr/local/bin/icacam-fw --config /etc/icacam/device.conf --check
systemctl daemon-reload
systemctl enable icacam-fw
systemctl restart icacam-fw
systemctl --no-pager status icacam-fw | head -5
