#!/usr/bin/env bash
# Builds lastcut's Debian package from a clean checkout of HEAD (git archive, so nothing
# uncommitted or built slips in), then checks it with lintian and fails on any error.
# Output: dist/lastcut_VERSION_ARCH.deb and dist/lintian.txt. Needs root (or sudo) for apt.
set -euo pipefail
cd "$(dirname "$0")/.."
root="$(pwd)"
bash scripts/setup.sh  # installs the packaging tools too (debhelper, dpkg-dev, fakeroot, lintian, help2man)
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
# -J: in parallel (debhelper builds with one job unless DEB_BUILD_OPTIONS holds parallel=N).
git archive --format=tar --prefix=lastcut/ HEAD | tar -x -C "$work"
# The archive has no working tree for the symlinks' targets to be missed: check them.
(cd "$work/lastcut" && dpkg-checkbuilddeps && dpkg-buildpackage -us -uc -b -J"$(nproc)") >"$work/build.log" 2>&1 ||
  { tail -40 "$work/build.log"; echo "package: dpkg-buildpackage failed (log above)" >&2; exit 1; }
mkdir -p "$root/dist"
cp "$work"/lastcut_*.deb "$root/dist/"
deb="$(ls -t "$root"/dist/lastcut_*.deb | head -1)"
echo "package: built $deb"
dpkg-deb --info "$deb" | sed -n '/Package:/,/Description:/p'
lintian --no-tag-display-limit "$deb" | tee "$root/dist/lintian.txt" || true
if grep -q '^E:' "$root/dist/lintian.txt"; then
  echo "package: lintian reports errors" >&2; exit 1
fi
echo "package: lintian reports no errors ($(grep -c '^W:' "$root/dist/lintian.txt" || true) warnings)"
