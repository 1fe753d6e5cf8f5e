# Shared start of the CLI test scripts, sourced as `. "$(dirname "$0")/cli_test_lib.sh"` by a
# script called as `SCRIPT TACTILE WORKDIR`: sets T (the program) and W (a fresh work folder, the
# current folder from here on) and defines fail.
set -eu
T=$1
W=$2
rm -rf "$W"
mkdir -p "$W"
cd "$W"
fail() {
  echo "FAIL: $*" >&2
  exit 1
}
