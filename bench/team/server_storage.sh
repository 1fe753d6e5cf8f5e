#!/usr/bin/env bash
# Import, copy and open figures of a PostgreSQL server beside an SQLite file, each round on a fresh
# private server (a server reused by earlier rounds holds their deleted rows until autovacuum runs).
# Usage: bench/team/server_storage.sh TACTILE [ROUNDS] [-- extra `tactile bench storage` options]
set -euo pipefail
tactile=${1:?usage: server_storage.sh TACTILE [ROUNDS]}
rounds=${2:-3}
shift $(($# >= 2 ? 2 : 1))
[ "${1:-}" = "--" ] && shift
here=$(cd "$(dirname "$0")" && pwd)
cluster=$here/../../tests/support/pg_cluster.sh
state=$(mktemp)
work=$(mktemp -d)
trap 'bash "$cluster" stop "$state" >/dev/null 2>&1 || true; rm -rf "$work" "$state"' EXIT
for ((r = 1; r <= rounds; r++)); do
  bash "$cluster" start "$state" >/dev/null
  address=$(head -1 "$state" | cut -d' ' -f1)
  "$tactile" db create --db "$address" >/dev/null
  rm -rf "$work/round"
  "$tactile" bench storage --steps 1000000 --files 8 --big-steps 1000000 --repeats 5 --no-compare \
    --server "$address" --dir "$work/round" --json "$@" | tail -1
  bash "$cluster" stop "$state" >/dev/null
done
