#!/bin/sh
# The interoperability tests (tests/interop/interop.mjs) through the command line:
#  1. ROS 2 bags written by the reference writer (zstd and uncompressed) import with their values;
#  2. an export, and the import-export chain, read back by the reference reader.
# Needs node and the packages of package-lock.json (`npm ci` in tests/interop; scripts/test.sh
# runs it).
#   tests/interop/run_interop.sh TACTILE WORKDIR
. "$(dirname "$0")/../app/cli_test_lib.sh"
HERE=$(cd "$(dirname "$0")" && pwd)
[ -d "$HERE/node_modules/@mcap/core" ] || fail "the npm packages are missing: run 'npm ci' in $HERE (scripts/test.sh does)"
command -v node > /dev/null || fail "node is missing (scripts/deps.sh installs it)"
I="$HERE/interop.mjs"

# 1. Bags from the reference writer.
node "$I" write-bags bags || fail "writing the bags"
for c in zstd none; do
  "$T" mcap info "bags/bag_$c.mcap" > "info_$c.txt" || fail "mcap info bag_$c"
  grep -q "/tactile .* std_msgs/msg/Float32MultiArray \[ros2msg\] (cdr)" "info_$c.txt" || fail "info: $(cat "info_$c.txt")"
  "$T" import --db "bag_$c.db" "bags/bag_$c.mcap" --mapping bags/mapping.json > /dev/null || fail "import of bag_$c"
  "$T" export-run --db "bag_$c.db" --run "bag_$c" --out "bag_$c.csv"
  node "$I" check-import bags/expected.json "bag_$c.csv" || fail "bag_$c values"
done

# 2. Our export through the reference reader.
"$T" simulate --scene room1 --driver wall-follow --steps 1500 --seed 2 --out r.csv --quiet > /dev/null
"$T" import --db r.db r.csv > /dev/null
"$T" autolabel --db r.db --run r --set truth > /dev/null
"$T" export-run --db r.db --run r --out r0.csv
"$T" export-run --db r.db --run r --format mcap --out r.mcap --sets truth > /dev/null
node "$I" check-export r.mcap r0.csv || fail "reference reader on our export"
# And a bag's run exported again.
"$T" export-run --db bag_zstd.db --run bag_zstd --format mcap --out bag_again.mcap > /dev/null
node "$I" check-export bag_again.mcap bag_zstd.csv || fail "reference reader on an imported bag's export"
echo "ok: reference writer's bags import value for value; reference reader reads our exports"
