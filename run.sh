#!/usr/bin/env bash
# bladebench's two set-up commands (see README.md):
#   ./run.sh all   install missing packages, build Release, run every case (with studies), write reports/
#   ./run.sh test  install missing packages, build Release, run the default test set (ctest, no 'study'
#                  label), then build with AddressSanitizer + UBSan (clang) and run the unit and bad-input tests
# Extra: ./run.sh asan  only the sanitizer part of 'test'.
set -euo pipefail
cd "$(dirname "$0")"

PACKAGES=(build-essential cmake pkg-config libeigen3-dev libspectra-dev libtomlplusplus-dev libfccp-dev
          libceres-dev libsuitesparse-dev libmumps-seq-dev libopenblas0-pthread libfmt-dev libcli11-dev nlohmann-json3-dev libgtest-dev
          libbenchmark-dev gnuplot-nox libcmark-gfm-dev libcmark-gfm-extensions-dev libxxhash-dev chromium ccache
          clang libclang-rt-14-dev
          pybind11-dev python3-dev python3-numpy python3-pytest python3-meshio python3-pandas
          libslepc-real-dev libpetsc-real-dev openmpi-bin)

ensure_packages() {
  local missing=()
  for p in "${PACKAGES[@]}"; do
    dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
  done
  [ ${#missing[@]} -eq 0 ] && return 0
  if [ "$(id -u)" -ne 0 ]; then
    echo "Missing Debian packages. As root, run:" >&2
    echo "  apt-get update && apt-get install -y --no-install-recommends ${missing[*]}" >&2
    exit 2
  fi
  echo "Installing: ${missing[*]}" >&2
  apt-get update -qq
  DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
}

build() {
  local out
  out=$(cmake --preset "$1" 2>&1) || { echo "$out" >&2; exit 1; }
  # A tree configured with another compiler (GCC before 2026-11-29): CMake deletes its cache and
  # configures without the preset's variables (the asan tree without sanitizers); once more sets them.
  if grep -q "require your cache to be deleted" <<<"$out"; then
    cmake --preset "$1" >/dev/null
  fi
  cmake --build --preset "$1" -j "$(nproc)"
}

case "${1:-}" in
  all)
    ensure_packages
    build release
    # The studies are run on purpose: their finest levels may exceed the default work bound.
    ./build/solvers/bladebench validate cases --out reports --study --max-work 1e14 -j "$(nproc)"
    ;;
  test)
    ensure_packages
    build release
    ctest --preset release -j "$(nproc)"
    build asan
    ctest --preset asan -j "$(nproc)"
    ;;
  asan)
    ensure_packages
    build asan
    ctest --preset asan -j "$(nproc)"
    ;;
  *)
    echo "usage: ./run.sh all | test | asan" >&2
    exit 2
    ;;
esac
