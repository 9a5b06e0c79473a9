#!/usr/bin/env bash
# Installs lastcut's Debian package into a fresh Debian bookworm root (debootstrap from the Debian
# archive) and checks what an IT admin relies on: the configuration passes lastcutd's check, the
# system user exists and is in dialout, the spool folders exist and belong to it, systemd accepts
# the installed unit with an exposure of at most 2.0, and `dpkg --purge` leaves nothing behind
# but the system user (Debian policy keeps system users). Prints PASS/FAIL per check.
# Usage (as root): check_package.sh dist/lastcut_VERSION_ARCH.deb
set -euo pipefail
deb="$(readlink -f "$1")"
cache=/var/cache/lastcut-check
fresh="$cache/root-fresh"            # a minbase bookworm root, made once and copied per run
root="$(mktemp -d /var/tmp/lastcut-check.XXXXXX)"
failures=0
check() { # check NAME COMMAND...: runs the command, prints PASS or FAIL
  local name="$1"; shift
  if "$@" >"$root.out" 2>&1; then echo "PASS $name"; else echo "FAIL $name"; sed 's/^/     /' "$root.out" | tail -15; failures=$((failures + 1)); fi
}
cleanup() { umount "$root/proc" 2>/dev/null || true; rm -rf "$root" "$root.out" "$root".files-*; }
trap cleanup EXIT

if [ ! -x "$fresh/bin/sh" ]; then
  mkdir -p "$cache"
  debootstrap --variant=minbase bookworm "$fresh" http://deb.debian.org/debian
fi
cp -a "$fresh/." "$root/"
mount -t proc proc "$root/proc"
echo "deb http://deb.debian.org/debian bookworm main" >"$root/etc/apt/sources.list"
chroot "$root" apt-get update -q >/dev/null
# systemd in the root: the unit's checks run with the root's own systemd-analyze.
chroot "$root" env DEBIAN_FRONTEND=noninteractive apt-get install -y -q --no-install-recommends systemd >/dev/null
snapshot() { (cd "$root" && find . -xdev \( -path ./proc -o -path ./run -o -path ./var/cache/apt -o -path ./var/lib/apt/lists -o -path ./tmp \) -prune -o -print | sort) >"$1"; }
snapshot "$root.files-before"

cp "$deb" "$root/tmp/"
check "apt install ./$(basename "$deb")" chroot "$root" env DEBIAN_FRONTEND=noninteractive apt-get install -y -q "/tmp/$(basename "$deb")"
check "lastcut --help runs" chroot "$root" lastcut --help
check "lastcutd --check-config /etc/lastcut/lastcut.toml" chroot "$root" lastcutd --check-config /etc/lastcut/lastcut.toml
check "user lastcut exists" chroot "$root" getent passwd lastcut
check "user lastcut is in dialout" sh -c "chroot '$root' id -nG lastcut | tr ' ' '\n' | grep -qx dialout"
check "spool folders exist, owned by lastcut" sh -c "chroot '$root' stat -c '%U %n' /var/spool/lastcut /var/spool/lastcut/incoming | grep -c '^lastcut ' | grep -qx 2"
check "conffile /etc/lastcut/lastcut.toml" sh -c "chroot '$root' dpkg-query -W -f='\${Conffiles}' lastcut | grep -q /etc/lastcut/lastcut.toml"
check "man pages" chroot "$root" test -f /usr/share/man/man1/lastcut.1.gz -a -f /usr/share/man/man8/lastcutd.8.gz -a -f /usr/share/man/man5/lastcut.toml.5.gz
check "systemd-analyze verify lastcutd.service" chroot "$root" systemd-analyze verify --man=no /lib/systemd/system/lastcutd.service
exposure() {
  local level
  level="$(chroot "$root" systemd-analyze security --offline=true /lib/systemd/system/lastcutd.service 2>&1 |
           sed -n 's/.*Overall exposure level for lastcutd.service: \([0-9.]*\).*/\1/p')"
  echo "exposure $level"
  [ -n "$level" ] && awk -v l="$level" 'BEGIN { exit !(l <= 2.0) }'
}
check "systemd-analyze security: exposure <= 2.0" exposure
cat "$root.out" | grep -m1 exposure || true

check "dpkg --purge lastcut" chroot "$root" dpkg --purge lastcut
# The libraries apt installed for it were marked automatic: they go too.
chroot "$root" env DEBIAN_FRONTEND=noninteractive apt-get autoremove --purge -y -q >/dev/null
snapshot "$root.files-after"
left="$(comm -13 "$root.files-before" "$root.files-after" | grep -v -E '^\./etc/(passwd|group|shadow|gshadow|subuid|subgid)-?$' || true)"
purge_clean() { [ -z "$left" ] || { echo "left after purge:"; echo "$left"; return 1; }; }
check "purge leaves nothing but the system user" purge_clean
echo "system user after purge (kept by policy): $(chroot "$root" getent passwd lastcut || echo none)"

[ "$failures" -eq 0 ] && echo "check_package: all checks passed" || { echo "check_package: $failures check(s) failed"; exit 1; }
