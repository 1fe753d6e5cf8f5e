#!/bin/sh
# The workbench without a display: --help and --version answer, a screenshot renders off screen, and
# anything else fails with a message that says why instead of Qt's platform-plugin error.
# Usage: workbench_headless.sh WORKBENCH OUTDIR
set -u
W=$1
O=$2
rm -rf "$O" && mkdir -p "$O"
fail() { echo "FAIL: $*"; exit 1; }
# A home of its own: the user's settings (the last database) are neither read nor changed.
nodisplay() { env -u DISPLAY -u WAYLAND_DISPLAY -u QT_QPA_PLATFORM HOME="$O" XDG_CONFIG_HOME="$O/config" LC_ALL=C "$@"; }

nodisplay "$W" --help >"$O/help.out" 2>"$O/help.err" || fail "--help exited $?: $(cat "$O/help.err")"
grep -q -- '--simulate <SCENE>' "$O/help.out" || fail "--help does not list --simulate"
grep -q -- '--screenshot <FILE>' "$O/help.out" || fail "--help does not list --screenshot"
nodisplay "$W" --version >"$O/version.out" 2>&1 || fail "--version exited $?"
grep -q '^tactile-workbench [0-9]' "$O/version.out" || fail "--version printed: $(cat "$O/version.out")"

nodisplay "$W" --db "$O/none.db" >"$O/open.out" 2>"$O/open.err"
rc=$?
[ $rc -eq 1 ] || fail "no display: exit $rc, not 1"
grep -q 'error: no display' "$O/open.err" || fail "no display: message was: $(cat "$O/open.err")"
[ ! -e "$O/none.db" ] || fail "no display: a database was created"

nodisplay "$W" --screenshot "$O/shot.png" >"$O/shot.out" 2>&1 || fail "--screenshot exited $?: $(cat "$O/shot.out")"
head -c 8 "$O/shot.png" | od -An -c | grep -q 'P   N   G' || fail "--screenshot wrote no PNG"
nodisplay "$W" --screenshot="$O/shot2.png" >"$O/shot2.out" 2>&1 || fail "--screenshot=FILE exited $?"
[ -s "$O/shot2.png" ] || fail "--screenshot=FILE wrote nothing"
echo "ok: the workbench without a display"
