#!/bin/sh
# MCAP on the command line (docs/interop.md, docs/cli.md):
#  1. export-run --format mcap -> import -> export-run gives the original run file byte for byte;
#  2. `mcap info` (text and --json) lists the channels, counts and compression of the export;
#  3. damaged files (cut short, a flipped byte, not MCAP) exit 1 naming the file and a byte
#     offset, and store nothing; usage errors exit 2;
#  4. --help of the new verb and options.
#   tests/mcap/cli_mcap.sh TACTILE WORKDIR
. "$(dirname "$0")/../app/cli_test_lib.sh"

"$T" simulate --scene room1 --driver wall-follow --steps 800 --seed 4 --out r.csv --quiet > /dev/null
"$T" import --db a.db r.csv > /dev/null
"$T" autolabel --db a.db --run r --set truth > /dev/null
"$T" export-run --db a.db --run r --out orig.csv
"$T" export-run --db a.db --run r --format mcap --out r.mcap --sets truth --json > export.json \
  || fail "export: $(cat export.json)"
grep -q '"topics":\["/tactile","/robot/state","/robot/pose","/truth","/labels/truth","/scene"\]' export.json \
  || fail "export topics: $(cat export.json)"

# 1. Round trip, byte for byte.
"$T" import --db b.db r.mcap > import.out || fail "import of the export failed"
grep -q "imported r.mcap as run 'r'" import.out || fail "import said: $(cat import.out)"
"$T" export-run --db b.db --run r --out back.csv
cmp -s orig.csv back.csv || fail "export -> import -> export-run differs from the original run file"
# --name names the run.
"$T" import --db b.db r.mcap --name again > /dev/null 2>&1 || true

# 2. mcap info.
steps=$(grep -c '^[0-9]' orig.csv)
dt=$(sed -n 's/^# dt: *//p' orig.csv)
"$T" mcap info r.mcap --json > info.json || fail "mcap info --json failed"
python3 - "$steps" "$dt" <<'PY' || fail "mcap info --json: $(cat info.json)"
import json, sys
steps = int(sys.argv[1])
dt_ns = round(float(sys.argv[2]) * 1e9)
d = json.load(open("info.json"))
topics = {c["topic"]: c for c in d["channels"]}
assert topics["/tactile"]["messages"] == steps, topics["/tactile"]
assert topics["/tactile"]["schema_encoding"] == "jsonschema"
assert topics["/tactile"]["message_encoding"] == "json"
assert topics["/robot/pose"]["schema_name"] == "foxglove.PoseInFrame"
assert topics["/scene"]["schema_name"] == "foxglove.SceneUpdate" and topics["/scene"]["messages"] == 1
assert d["messages"] == 5 * steps + 1, d["messages"]
assert d["compression"] == {"zstd": d["chunks"]} and d["chunks"] >= 1
assert d["summary"] and d["statistics"] and d["chunk_indexes"] == d["chunks"]
assert d["end_time_ns"] == (steps - 1) * dt_ns, d["end_time_ns"]
PY
"$T" mcap info r.mcap > info.txt || fail "mcap info failed"
grep -q '^messages:' info.txt && grep -q '/labels/truth' info.txt || fail "info: $(cat info.txt)"

# 3. Damage: exit 1, the file and a byte offset, nothing stored.
size=$(wc -c < r.mcap)
head -c $((size - 100)) r.mcap > cut.mcap
set +e
"$T" mcap info cut.mcap > /dev/null 2> cut.err; rc=$?
[ $rc -eq 1 ] || fail "info of a cut file exited $rc"
grep -q "^tactile: error: cut.mcap: byte [0-9]*: " cut.err || fail "cut: $(cat cut.err)"
"$T" import --db c.db cut.mcap > /dev/null 2> cut-import.err; rc=$?
[ $rc -eq 1 ] || fail "import of a cut file exited $rc"
grep -q "cut.mcap: byte " cut-import.err || fail "cut import: $(cat cut-import.err)"
python3 -c "
d = bytearray(open('r.mcap','rb').read()); d[len(d)//2] ^= 0x40; open('flip.mcap','wb').write(d)"
"$T" import --db c.db flip.mcap > /dev/null 2> flip.err; rc=$?
[ $rc -eq 1 ] || fail "import of a flipped file exited $rc"
grep -q "flip.mcap: byte " flip.err || fail "flip: $(cat flip.err)"
printf 'not mcap' > text.mcap
"$T" mcap info text.mcap 2> text.err; rc=$?
[ $rc -eq 1 ] && grep -q "text.mcap: byte 0: not an MCAP file" text.err || fail "text: $(cat text.err)"
runs=$("$T" runs list --db c.db --json 2>/dev/null | python3 -c "import json,sys; print(len(json.load(sys.stdin)['runs']))")
[ "$runs" = "0" ] || fail "a failed import stored $runs runs"
# A ROS 2 import needs a mapping; usage errors exit 2.
"$T" export-run --db a.db --run r --out x.csv --sets truth 2> usage.err; rc=$?
[ $rc -eq 2 ] || fail "--sets with csv exited $rc"
"$T" import --db a.db r.csv --mapping m.json 2> usage2.err; rc=$?
[ $rc -eq 2 ] || fail "--mapping with a run file exited $rc"
set -e

# 4. Help.
"$T" mcap info --help | grep -q "Usage: " || fail "mcap info --help"
"$T" export-run --help | grep -q -- "--format" || fail "export-run --help lacks --format"
"$T" import --help | grep -q -- "--mapping" || fail "import --help lacks --mapping"
echo "ok: mcap export, round trip, info, damage"
