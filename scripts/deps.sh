#!/usr/bin/env bash
# Installs the Debian packages the build and the tests need, if any is missing.
# Sourced by run.sh and test.sh; as root it installs, with sudo it asks, otherwise it prints the
# exact command and fails.
set -euo pipefail

TACTILE_PACKAGES=(
  cmake g++ make pkg-config clang-format binutils
  qt6-base-dev qt6-tools-dev qt6-l10n-tools qt6-tools-dev-tools libgl-dev
  libqcustomplot-dev libqcustomplot2.1-qt6
  libeigen3-dev libsqlite3-dev sqlite3 libpq-dev postgresql nlohmann-json3-dev libcli11-dev
  libgtest-dev libgmock-dev libbenchmark-dev
  libzstd-dev liblz4-dev libxgboost-dev nodejs
  python3-dev pybind11-dev python3-numpy python3-pandas python3-sklearn python3-pytest
  xvfb xauth fonts-noto-cjk qt6-translations-l10n locales
  slurm-wlm munge
)

tactile_missing_packages() {
  local missing=()
  for p in "${TACTILE_PACKAGES[@]}"; do
    if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
      missing+=("$p")
    fi
  done
  echo "${missing[@]:-}"
}

tactile_install_deps() {
  local missing
  missing=$(tactile_missing_packages)
  [ -z "$missing" ] && return 0
  echo "Installing missing Debian packages: $missing"
  local apt=(env DEBIAN_FRONTEND=noninteractive apt-get)
  if [ "$(id -u)" -eq 0 ]; then
    "${apt[@]}" update -qq
    # shellcheck disable=SC2086
    "${apt[@]}" install -y -qq --no-install-recommends $missing
  elif command -v sudo >/dev/null 2>&1 && sudo -n true 2>/dev/null; then
    sudo "${apt[@]}" update -qq
    # shellcheck disable=SC2086
    sudo "${apt[@]}" install -y -qq --no-install-recommends $missing
  else
    echo "These Debian packages are missing. Install them as root, then run this script again:" >&2
    echo "  apt-get install $missing" >&2
    return 1
  fi
}

# npm for the interoperability tests (tests/interop): Debian's `npm` package, unless the
# installed nodejs brings its own npm (some nodejs builds do, and then conflict with Debian's npm).
tactile_install_npm() {
  command -v npm > /dev/null 2>&1 && return 0
  local apt=(env DEBIAN_FRONTEND=noninteractive apt-get)
  echo "Installing the Debian package npm"
  if [ "$(id -u)" -eq 0 ]; then
    "${apt[@]}" update -qq
    "${apt[@]}" install -y -qq --no-install-recommends npm
  elif command -v sudo >/dev/null 2>&1 && sudo -n true 2>/dev/null; then
    sudo "${apt[@]}" update -qq
    sudo "${apt[@]}" install -y -qq --no-install-recommends npm
  else
    echo "npm is missing. Install it as root, then run this script again:" >&2
    echo "  apt-get install npm" >&2
    return 1
  fi
}

# Generates the German locale (de_DE.UTF-8) if it is missing: the tests check that a decimal comma
# in the process's locale never reaches the figures and tables (ReportSvg.NumbersIgnoreTheLocale).
# As root it generates it, with sudo it asks, otherwise it prints the exact command and fails.
tactile_install_locale() {
  if locale -a 2>/dev/null | grep -qix 'de_DE\.utf-\?8'; then
    return 0
  fi
  local make=(localedef -i de_DE -f UTF-8 de_DE.UTF-8)
  echo "Generating the locale de_DE.UTF-8 for the tests"
  if [ "$(id -u)" -eq 0 ]; then
    "${make[@]}"
  elif command -v sudo >/dev/null 2>&1 && sudo -n true 2>/dev/null; then
    sudo "${make[@]}"
  else
    echo "The locale de_DE.UTF-8 is missing. Generate it as root, then run this script again:" >&2
    echo "  ${make[*]}" >&2
    return 1
  fi
}

# Configures and builds the Release tree in build/ (reused when it exists). Further arguments
# are CMake options, e.g. -DTACTILE_WERROR=ON (developers and CI).
tactile_build() {
  local root=$1
  shift
  local jobs
  jobs=$(nproc 2>/dev/null || echo 2)
  if [ ! -f "$root/build/CMakeCache.txt" ] || [ $# -gt 0 ]; then
    cmake -S "$root" -B "$root/build" -DCMAKE_BUILD_TYPE=Release "$@"
  fi
  cmake --build "$root/build" -j"$jobs"
}
