#!/usr/bin/env bash
# Installs what is missing, builds (reusing build/), and runs every test.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
# shellcheck source=scripts/deps.sh
source "$root/scripts/deps.sh"
tactile_install_deps
tactile_install_npm
tactile_install_locale
# The reference MCAP implementation for the interoperability tests, exactly as locked.
(cd "$root/tests/interop" && npm ci --no-audit --no-fund --loglevel=error)
# Warnings are errors here (developers and CI), never in scripts/run.sh.
tactile_build "$root" -DTACTILE_WERROR=ON
cd "$root/build"
export QT_QPA_PLATFORM=offscreen
ctest --output-on-failure -j"$(nproc 2>/dev/null || echo 2)" --timeout 600
