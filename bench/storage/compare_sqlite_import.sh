#!/bin/sh
# Side-by-side import comparison: `tactile import` against the sqlite3 shell's `.import --csv` of
# the same run files into a plain table (same page size, WAL, synchronous=NORMAL), several rounds.
#   bench/storage/compare_sqlite_import.sh [TACTILE] [ROUNDS] [STEPS] [FILES]
# Prints one JSON line per round (see docs/bench-storage.md for the fields).
set -eu
TACTILE=${1:-build/app/tactile}
ROUNDS=${2:-3}
STEPS=${3:-1000000}
FILES=${4:-8}
command -v sqlite3 > /dev/null || { echo "sqlite3 shell not found" >&2; exit 1; }
i=1
while [ "$i" -le "$ROUNDS" ]; do
  echo "# round $i, $(uptime)" >&2
  "$TACTILE" bench storage --steps "$STEPS" --files "$FILES" --big-steps "$STEPS" --json
  i=$((i + 1))
done
