#!/usr/bin/env bash
# Installs what is missing, builds Release into build/, and opens the workbench.
# Extra arguments are passed to the workbench.
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
# shellcheck source=scripts/deps.sh
source "$root/scripts/deps.sh"
tactile_install_deps
tactile_build "$root"
exec "$root/build/app/tactile-workbench" "$@"
