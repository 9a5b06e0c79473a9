#!/usr/bin/env bash
# Installs everything lastcut needs to build, test and run, from Debian bookworm packages
# (and, for the independent G-code and Modbus interpreters the tests use, the npm registry).
# Idempotent: safe to run before every build. Needs root (or sudo).
#   bash scripts/setup.sh              everything: build, run, test, fuzz, package
#   bash scripts/setup.sh --programs   only what lastcut, lastcutd and lastcut-sim need (the demo)
set -euo pipefail
cd "$(dirname "$0")/.."

# What the three programs (lastcut, lastcutd, lastcut-sim) need to build and run: all that
# `scripts/setup.sh --programs` installs (the demo's first run on a fresh machine).
PROGRAM_PACKAGES=(
  # build
  cmake ninja-build g++ pkg-config ccache git
  # engine
  libeigen3-dev libopenmesh-dev libsuitesparse-dev libpolyclipping-dev nlohmann-json3-dev
  # drivers, daemon, command line
  libserialport-dev libmodbus-dev libspdlog-dev libfmt-dev libtomlplusplus-dev libcli11-dev libsystemd-dev
  # live status over MQTT, the multi-station job ledger (PostgreSQL), the operator page
  libmosquitto-dev libpqxx-dev libcpp-httplib-dev
)
# The rest, for the tests, benchmarks, fuzzing and packaging.
TEST_PACKAGES=(
  # the servers the tests start themselves: the MQTT broker, PostgreSQL
  mosquitto postgresql
  # the real browser the operator page's tests drive
  chromium
  # tests and benchmarks
  libgtest-dev libgmock-dev libbenchmark-dev
  # independent interpreters and tools the tests run against our output
  hp2xx mbpoll socat systemd procps python3 openssl
  # DXF-AAMA pattern files (tests/pattern): ezdxf reads and audits them, LibreCAD renders them to
  # PDF (dxf2pdf, headless) and poppler's pdftoppm turns the page into a picture; Valentina, the
  # pattern-making program, exports a hand-written pattern as DXF-AAMA for lastcut to cut
  python3-ezdxf librecad poppler-utils valentina
  # the real grbl 1.1h firmware simulator (tests/peers) and the load it is tested under
  make gcc
  # fuzzing the parsers (clang's libFuzzer, tests/fuzz)
  clang libclang-rt-14-dev llvm
  # the Debian package and its check in a fresh bookworm root (scripts/package.sh, check_package.sh)
  debhelper dpkg-dev fakeroot lintian help2man debootstrap
)
programs_only=false
if [ "${1:-}" = "--programs" ]; then programs_only=true; fi
DEBIAN_PACKAGES=("${PROGRAM_PACKAGES[@]}")
if ! $programs_only; then DEBIAN_PACKAGES+=("${TEST_PACKAGES[@]}"); fi

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

if $programs_only; then
  echo "setup: the programs' dependencies present"
  exit 0
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
