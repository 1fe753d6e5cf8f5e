#!/usr/bin/env bash
# A private PostgreSQL server for the tests: `start STATE` makes a cluster with initdb in a fresh
# temporary folder, starts it listening only on a Unix socket there (no TCP port) and writes its
# address to STATE; `stop STATE` stops it (immediately) and removes the folder. No system service is
# touched. As root, the server runs as the `postgres` account (PostgreSQL refuses root).
set -euo pipefail

action=${1:?usage: pg_cluster.sh start|stop|crash|restart STATE-FILE}
state=${2:?usage: pg_cluster.sh start|stop|crash|restart STATE-FILE}

bindir=""
for candidate in "$(pg_config --bindir 2>/dev/null || true)" /usr/lib/postgresql/*/bin; do
  if [ -n "$candidate" ] && [ -x "$candidate/initdb" ] && [ -x "$candidate/pg_ctl" ]; then
    bindir=$candidate
    break
  fi
done
if [ -z "$bindir" ]; then
  echo "pg_cluster.sh: initdb and pg_ctl not found (apt-get install postgresql)" >&2
  exit 1
fi

as_owner() {
  if [ "$(id -u)" -eq 0 ]; then
    runuser -u postgres -- "$@"
  else
    "$@"
  fi
}

case "$action" in
  start)
    if [ -f "$state" ]; then "$0" stop "$state" || true; fi
    dir=$(mktemp -d /tmp/tactile-pg.XXXXXX)
    chmod 755 "$dir"
    if [ "$(id -u)" -eq 0 ]; then chown postgres: "$dir"; fi
    as_owner "$bindir/initdb" -D "$dir/data" -U postgres --auth=trust --encoding=UTF8 \
      --locale=C.UTF-8 >"$dir/initdb.log" 2>&1 || { cat "$dir/initdb.log" >&2; exit 1; }
    as_owner "$bindir/pg_ctl" -D "$dir/data" -l "$dir/server.log" -w -t 60 \
      -o "-c listen_addresses='' -c unix_socket_directories='$dir' -c fsync=off \
          -c max_connections=100 -c shared_buffers=128MB" start >/dev/null ||
      { cat "$dir/server.log" >&2; exit 1; }
    as_owner "$bindir/createdb" -h "$dir" -U postgres tactile_test
    mkdir -p "$(dirname "$state")"
    printf '%s\n%s\n' "postgresql:///tactile_test?host=$dir&user=postgres" "$dir" >"$state"
    echo "PostgreSQL $("$bindir/postgres" --version | awk '{print $3}') on $dir"
    ;;
  crash)
    # The server stops at once, as at a power cut of its machine: no checkpoint, clients cut off.
    dir=$(sed -n 2p "$state")
    as_owner "$bindir/pg_ctl" -D "$dir/data" -m immediate -w stop >/dev/null
    ;;
  restart)
    dir=$(sed -n 2p "$state")
    as_owner "$bindir/pg_ctl" -D "$dir/data" -l "$dir/server.log" -w -t 60 \
      -o "-c listen_addresses='' -c unix_socket_directories='$dir' -c fsync=off \
          -c max_connections=100 -c shared_buffers=128MB" start >/dev/null ||
      { cat "$dir/server.log" >&2; exit 1; }
    ;;
  stop)
    [ -f "$state" ] || exit 0
    dir=$(sed -n 2p "$state")
    if [ -n "$dir" ] && [ -d "$dir/data" ]; then
      as_owner "$bindir/pg_ctl" -D "$dir/data" -m immediate -w stop >/dev/null 2>&1 || true
    fi
    case "$dir" in /tmp/tactile-pg.*) rm -rf "$dir" ;; esac
    rm -f "$state"
    ;;
  *)
    echo "usage: pg_cluster.sh start|stop|crash|restart STATE-FILE" >&2
    exit 2
    ;;
esac
