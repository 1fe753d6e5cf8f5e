#!/bin/sh
# Usage: cli_expect_output.sh PATTERN COMMAND [ARGS...]
# Runs the command and passes when it exits with status 0 and a line of its output (stdout and
# stderr) matches the extended regular expression PATTERN. A PASS_REGULAR_EXPRESSION alone makes
# CTest ignore the exit status, so a command that printed the text and then failed would pass.
set -u
pattern=$1
shift
out=$("$@" 2>&1)
status=$?
if [ "$status" -ne 0 ]; then
  printf '%s\n' "$out"
  echo "FAIL: '$*' exited with status $status (expected 0)"
  exit 1
fi
if ! printf '%s\n' "$out" | grep -Eq -- "$pattern"; then
  printf '%s\n' "$out"
  echo "FAIL: no line of the output of '$*' matches '$pattern'"
  exit 1
fi
echo "ok: '$*' exited 0 and printed a line matching '$pattern'"
