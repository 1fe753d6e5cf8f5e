#!/bin/sh
# `tactile simulate --follow-side`: the wall follower keeps the wall on the side given (whatever
# its seed draws), says so in its JSON, and the side is refused where no wall is followed.
. "$(dirname "$0")/cli_test_lib.sh"

# Contact steps of a group: the run's steps minus its NoContact steps.
contact() {
  python3 -c 'import json,sys; j=json.load(open(sys.argv[1])); c=j["class_steps"][sys.argv[2]]; print(j["steps"] - c["NoContact"])' "$1" "$2"
}
for seed in 11 14; do
  for side in left right; do
    "$T" simulate --scene random:office:3 --driver wall-follow --steps 3000 --seed $seed \
      --follow-side $side --out "$W/$side$seed.csv" --json --quiet >"$W/$side$seed.json" ||
      fail "simulate --follow-side $side (seed $seed) failed"
    python3 -c 'import json,sys; assert json.load(open(sys.argv[1]))["follow_side"] == sys.argv[2]' \
      "$W/$side$seed.json" $side || fail "JSON does not name side $side"
    l=$(contact "$W/$side$seed.json" L)
    r=$(contact "$W/$side$seed.json" R)
    if [ $side = left ]; then
      [ "$l" -gt 100 ] && [ "$l" -gt $((5 * r)) ] || fail "seed $seed left: L $l, R $r contact steps"
    else
      [ "$r" -gt 100 ] && [ "$r" -gt $((5 * l)) ] || fail "seed $seed right: L $l, R $r contact steps"
    fi
  done
done
# Without the option the seed decides (11 left, 14 right): the same runs as with its own side.
"$T" simulate --scene random:office:3 --driver wall-follow --steps 3000 --seed 11 \
  --out "$W/own11.csv" --quiet >/dev/null || fail "simulate without a side failed"
cmp -s "$W/own11.csv" "$W/left11.csv" || fail "seed 11 with its own side differs from its run"

usage() {
  status=0
  "$T" simulate "$@" --out "$W/x.csv" --quiet >/dev/null 2>"$W/usage.err" || status=$?
  [ "$status" -eq 2 ] || fail "exit $status (not 2) for: $*"
}
usage --scene room1 --driver random --follow-side left
usage --scene room1 --follow-side up
usage --plan training --runs 2 --follow-side left
# The recipe chooses driver, length and step itself: those options are refused with it.
for opt in "--driver random" "--steps 100" "--dt 0.05" "--threads 2"; do
  status=0
  # shellcheck disable=SC2086
  "$T" simulate --plan training --runs 2 $opt --out-dir "$W/plan" --quiet >/dev/null \
    2>"$W/usage.err" || status=$?
  [ "$status" -eq 2 ] || fail "exit $status (not 2) for --plan with $opt"
  grep -q "excludes" "$W/usage.err" || fail "--plan with $opt: $(cat "$W/usage.err")"
done
"$T" simulate --help | grep -q -- "--follow-side" || fail "--help does not name --follow-side"
echo "ok: follow-side"
