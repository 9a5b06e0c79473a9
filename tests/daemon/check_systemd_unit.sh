#!/usr/bin/env bash
# The systemd unit passes `systemd-analyze verify` and `systemd-analyze security --offline=true`
# rates it at most 2.0 (printed). The unit is checked as shipped, except that ExecStart points
# at the lastcutd just built (verify insists that the program exists).
# Usage: check_systemd_unit.sh SYSTEMD_FOLDER LASTCUTD_BINARY
set -euo pipefail
unit_dir="$1"
binary="$2"
command -v systemd-analyze >/dev/null || { echo "FAIL: systemd-analyze is missing (scripts/setup.sh installs systemd)"; exit 1; }
[ -x "$binary" ] || { echo "FAIL: $binary is not built"; exit 1; }
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
sed "s#/usr/bin/lastcutd#$binary#g" "$unit_dir/lastcutd.service" > "$work/lastcutd.service"

echo "== systemd-analyze verify"
if ! systemd-analyze verify "$work/lastcutd.service" 2>&1 | tee "$work/verify.txt"; then
  echo "FAIL: systemd-analyze verify"; exit 1
fi
if grep -v "^$" "$work/verify.txt" | grep -q .; then echo "FAIL: verify printed warnings"; exit 1; fi

echo "== systemd-analyze security --offline=true"
systemd-analyze security --offline=true "$work/lastcutd.service" > "$work/security.txt" 2>&1 || true
grep -E "^✗" "$work/security.txt" || true
score="$(grep -oE 'Overall exposure level for lastcutd.service: [0-9]+\.[0-9]+' "$work/security.txt" | grep -oE '[0-9]+\.[0-9]+$')"
[ -n "$score" ] || { echo "FAIL: no exposure level in:"; cat "$work/security.txt"; exit 1; }
echo "exposure level: $score (must be <= 2.0)"
awk -v s="$score" 'BEGIN { exit !(s <= 2.0) }' || { echo "FAIL: exposure $score > 2.0"; exit 1; }

echo "== required settings"
for setting in "Type=notify" "WatchdogSec=" "Restart=on-failure" "SupplementaryGroups=dialout" \
               "ProtectSystem=strict" "ReadWritePaths=/var/spool/lastcut" "PrivateDevices=no" "NotifyAccess=main"; do
  grep -q "^$setting" "$unit_dir/lastcutd.service" || { echo "FAIL: $setting missing"; exit 1; }
done
grep -q "^u lastcut" "$unit_dir/lastcut.sysusers.conf" || { echo "FAIL: sysusers entry missing"; exit 1; }
grep -q "^m lastcut dialout" "$unit_dir/lastcut.sysusers.conf" || { echo "FAIL: dialout membership missing"; exit 1; }
echo "OK"
