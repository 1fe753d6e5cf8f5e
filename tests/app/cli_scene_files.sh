#!/bin/sh
# Scene files and run files through the CLI (docs/file-formats.md#run-file, docs/cli.md#simulate):
#  1. `simulate --scene my.json` writes the scene beside its runs and names that file, so import
#     stores the run with its walls, even when the scene is called like a built-in one;
#  2. a scene whose name holds a line break is refused by simulate (no run file import rejects);
#  3. a creating verb that fails on a full disk (a file-size limit here) leaves no database file;
#  4. the database keeps checksums: a value changed behind its back fails `db check` and export,
#     and no writing verb writes into it.
#   tests/app/cli_scene_files.sh TACTILE WORKDIR
. "$(dirname "$0")/cli_test_lib.sh"

# ---- 1. a user's scene file called "practice", other geometry than the built-in ----------------
cat > mine.json <<'JSON'
{"name": "practice", "bounds": [0, 0, 2000, 1000],
 "obstacles": [{"polygon": [[1000, 100], [1100, 100], [1100, 900], [1000, 900]]}],
 "start": {"x": 200, "y": 500, "theta": 0}, "goal": {"x": 1800, "y": 500}}
JSON
mkdir one
"$T" simulate --scene mine.json --steps 60 --out one/single.csv --quiet > /dev/null
[ -f one/single.scene.json ] || fail "no scene file beside one/single.csv"
grep -q '^# scene: single.scene.json' one/single.csv || fail "run names $(grep scene one/single.csv)"
"$T" simulate --scene mine.json --steps 60 --runs 2 --out-dir batch --prefix b --quiet > /dev/null
[ -f batch/b.scene.json ] || fail "no scene file beside the batch"
grep -q '^# scene: b.scene.json' batch/b_0000.csv || fail "batch run names the wrong scene"
"$T" import --db s.db one/single.csv batch > import.out 2> import.err || fail "import: $(cat import.err)"
! grep -q "warning" import.err || fail "import warned: $(cat import.err)"
# Stored with its own walls (x 1000..1100, bounds 2000 wide), not the built-in practice geometry.
n=$(sqlite3 s.db "SELECT count(*) FROM runs JOIN scenes ON scenes.id = runs.scene_id WHERE scenes.json LIKE '%1100%' AND scenes.json LIKE '%2000%'")
[ "$n" -eq 3 ] || fail "$n of 3 runs stored with the user's scene"
n=$(sqlite3 s.db "SELECT count(*) FROM scenes WHERE json LIKE '%850%'")
[ "$n" -eq 0 ] || fail "the built-in practice geometry was stored"

# ---- 2. a scene name with a line break -----------------------------------------------------------
printf '{"name": "two\\nlines", "bounds": [0, 0, 1000, 1000], "obstacles": [],\n "start": {"x": 200, "y": 500, "theta": 0}, "goal": {"x": 800, "y": 500}}\n' > broken.json
set +e
"$T" simulate --scene broken.json --steps 20 --out broken.csv --quiet > /dev/null 2> broken.err
rc=$?
set -e
[ "$rc" -eq 1 ] || fail "simulate with a line break in the scene name exited $rc"
grep -q "broken.json.*control character" broken.err || fail "simulate: $(cat broken.err)"
[ ! -e broken.csv ] || fail "a run file was written"

# ---- 3. no 0-byte database when creation fails ----------------------------------------------------
set +e
(trap '' XFSZ; ulimit -f 0; "$T" db create --db full.db > /dev/null 2> full.err)
rc=$?
(trap '' XFSZ; ulimit -f 0; "$T" import --db full2.db one/single.csv > /dev/null 2> full2.err)
rc2=$?
set -e
[ "$rc" -eq 1 ] || fail "db create under a zero file-size limit exited $rc: $(cat full.err)"
[ "$rc2" -eq 1 ] || fail "import under a zero file-size limit exited $rc2: $(cat full2.err)"
for f in full.db full2.db; do
  for s in "" -wal -shm -journal; do
    [ ! -e "$f$s" ] || fail "$f$s left behind ($(wc -c < "$f$s") bytes)"
  done
done

# ---- 4. checksums --------------------------------------------------------------------------------
cp s.db d.db
sqlite3 d.db "UPDATE steps SET x = x + 1e-9 WHERE step = 7 AND run_id = (SELECT id FROM runs WHERE name = 'single')"
sum=$(sha256sum < d.db)
set +e
"$T" db check --db d.db > check.out 2> check.err
rc=$?
set -e
[ "$rc" -eq 1 ] || fail "db check on a changed value exited $rc"
grep -q "run 'single' (id [0-9]*) step 7" check.err check.out || fail "db check: $(cat check.out check.err)"
set +e
"$T" export-run --db d.db --run single --out single-export.csv 2> export.err
rc=$?
set -e
[ "$rc" -eq 1 ] || fail "export-run of a damaged run exited $rc"
grep -q "run 'single'.*damaged" export.err || fail "export-run: $(cat export.err)"
for verb in "import --db d.db one/single.csv" "runs rename --db d.db single other" \
            "autolabel --db d.db --all --set t" "db create --db d.db"; do
  set +e
  # shellcheck disable=SC2086
  "$T" $verb > verb.out 2> verb.err
  rc=$?
  set -e
  [ "$rc" -eq 1 ] || fail "$verb on a damaged database exited $rc"
  grep -q "d.db: damaged" verb.err || fail "$verb: $(cat verb.err)"
  [ "$(sha256sum < d.db)" = "$sum" ] || fail "$verb wrote into the damaged database"
done
echo "ok: scene files, names, failed creation, checksums"
