#!/bin/sh
# Runs scripts/translations.sh on copies of the .ts files and fails when that leaves an entry
# unfinished (a source string missing from a .ts file, or never translated).
set -eu
root=$1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
cp "$root"/translations/tactile_workbench_*.ts "$tmp/"
TACTILE_TS_DIR=$tmp sh -c "bash '$root/scripts/translations.sh'" >"$tmp/report.txt"
cat "$tmp/report.txt"
count=$(ls "$tmp"/tactile_workbench_*.ts | wc -l)
[ "$count" -ge 2 ] || { echo "expected at least two .ts files, found $count"; exit 1; }
if grep -v ': 0 unfinished$' "$tmp/report.txt" | grep -q unfinished; then
  echo "FAIL: strings of the sources are missing from the .ts files or unfinished; run scripts/translations.sh and translate them"
  for ts in "$tmp"/tactile_workbench_*.ts; do
    grep -B3 'type="unfinished"' "$ts" | grep '<source>' | head -20
  done
  exit 1
fi
echo "ok: every .ts file is current and finished"
