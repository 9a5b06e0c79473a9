#!/usr/bin/env bash
# Installs everything lastcut needs to build, test and run, from Debian bookworm packages
# (and, for the independent G-code and Modbus interpreters the tests use, the npm registry).
# Idempotent: safe to run before every build. Needs root (or sudo).
set -euo pipefail
cd "$(dirname "$0")/.."

DEBIAN_PACKAGES=(
  # build
  cmake ninja-build g++ pkg-config ccache git
  # engine
  libeigen3-dev libopenmesh-dev libsuitesparse-dev libpolyclipping-dev nlohmann-json3-dev
  # drivers, daemon, command line
  libserialport-dev libmodbus-dev libspdlog-dev libfmt-dev libtomlplusplus-dev libcli11-dev libsystemd-dev
  # live status over MQTT (the tests start the mosquitto broker themselves)
  libmosquitto-dev mosquitto
  # the multi-station job ledger (daemon/ledger) and the PostgreSQL server its tests start themselves
  libpqxx-dev postgresql
  # the operator page lastcutd serves, and the real browser its tests drive
  libcpp-httplib-dev chromium
  # tests and benchmarks
  libgtest-dev libgmock-dev libbenchmark-dev
  # independent interpreters and tools the tests run against our output
  hp2xx mbpoll socat systemd procps python3 openssl
  # the real grbl 1.1h firmware simulator (tests/peers) and the load it is tested under
  make gcc
  # fuzzing the parsers (clang's libFuzzer, tests/fuzz)
  clang libclang-rt-14-dev llvm
  # the Debian package and its check in a fresh bookworm root (scripts/package.sh, check_package.sh)
  debhelper dpkg-dev fakeroot lintian help2man debootstrap
)

SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi

missing=()
for package in "${DEBIAN_PACKAGES[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$package" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$package")
  fi
done
if [ ${#missing[@]} -gt 0 ]; then
  echo "setup: installing ${missing[*]}"
  $SUDO apt-get update -q
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -q --no-install-recommends "${missing[@]}"
fi

# Node.js runs the independent G-code, DXF and Modbus readers (tests/node). Debian's nodejs
# is used only when the machine has no node of its own.
if ! command -v node >/dev/null 2>&1; then
  DEBIAN_FRONTEND=noninteractive $SUDO apt-get install -y -q --no-install-recommends nodejs npm
fi
if [ -f tests/node/package.json ]; then
  (cd tests/node && npm ci --no-audit --no-fund --loglevel=error)
fi
echo "setup: all dependencies present"
