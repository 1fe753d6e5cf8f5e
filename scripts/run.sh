#!/usr/bin/env bash
# Installs what is missing, builds Release into build/, and opens the workbench. Without arguments
# it opens the demo database build/demo/demo.db, made on first use: two simulated wall-following
# runs in each built-in scene, imported, their truth turned into the label set "truth", and an
# empty set "annotations" to label in. Arguments are passed to the workbench instead
# (e.g. --db my.db --run NAME).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
# shellcheck source=scripts/deps.sh
source "$root/scripts/deps.sh"
tactile_install_deps
tactile_build "$root"

make_demo_database() {
  local db=$1 tactile=$root/build/app/tactile
  local work
  work=$(mktemp -d)
  trap 'rm -rf "$work"' RETURN
  echo "Creating the demo database $db ..."
  for scene in room1 room2 room3 chapter5; do
    "$tactile" simulate --scene "$scene" --runs 2 --steps 3000 --seed 1 --out-dir "$work/runs" \
      --prefix "$scene" --quiet >/dev/null
  done
  # Built in a temporary folder, copied next to its final name and renamed there (one atomic
  # step), so an interrupted first start never leaves half a demo database.
  "$tactile" import --db "$work/demo.db" "$work/runs" >/dev/null
  "$tactile" autolabel --db "$work/demo.db" --all --set truth >/dev/null
  printf 'run,group,first_step,last_step,class\n' >"$work/empty.csv"
  "$tactile" labels import --db "$work/demo.db" --set annotations "$work/empty.csv" >/dev/null
  mkdir -p "$(dirname "$db")"
  cp "$work/demo.db" "$db.partial"
  mv "$db.partial" "$db"
}

if [ $# -eq 0 ]; then
  demo=$root/build/demo/demo.db
  [ -f "$demo" ] || make_demo_database "$demo"
  set -- --db "$demo"
fi
exec "$root/build/app/tactile-workbench" "$@"
