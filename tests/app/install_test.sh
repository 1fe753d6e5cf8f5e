#!/bin/sh
# `cmake --install` into a fresh prefix: the programs, scenes, translations, desktop file and icons
# land where a desktop expects them, and the installed programs work from an unrelated folder with
# no settings: the CLI simulates and imports a built-in scene, the workbench opens the result and
# renders a screenshot, and it speaks German and Chinese from its own translations.
# Usage: install_test.sh CMAKE BUILD_DIR WORKDIR SCENE_DIR
set -eu
CMAKE=$1
BUILD=$2
W=$3
SCENES=$4
rm -rf "$W"
mkdir -p "$W/elsewhere" "$W/config"
fail() {
  echo "FAIL: $*" >&2
  exit 1
}
P=$W/prefix
"$CMAKE" --install "$BUILD" --prefix "$P" >"$W/install.log" || fail "cmake --install failed: $(cat "$W/install.log")"

for f in bin/tactile bin/tactile-workbench; do
  [ -x "$P/$f" ] || fail "$f not installed as a program"
done
n_src=$(ls "$SCENES"/*.json | wc -l)
n_inst=$(ls "$P"/share/tactile-workbench/scenes/*.json | wc -l)
[ "$n_src" -gt 0 ] && [ "$n_src" -eq "$n_inst" ] || fail "scenes: $n_inst installed of $n_src"
for lang in de zh_CN; do
  qm=$P/share/tactile-workbench/translations/tactile_workbench_$lang.qm
  [ -s "$qm" ] || fail "translation $lang not installed"
done
desktop=$P/share/applications/tactile-workbench.desktop
grep -q '^Exec=tactile-workbench' "$desktop" || fail "desktop file: no Exec line"
grep -q '^Icon=tactile-workbench$' "$desktop" || fail "desktop file: no Icon line"
grep -q '^Type=Application$' "$desktop" || fail "desktop file: no Type line"
if command -v desktop-file-validate >/dev/null 2>&1; then
  desktop-file-validate "$desktop" || fail "desktop file does not validate"
fi
icons=$P/share/icons/hicolor
grep -q '<svg' "$icons/scalable/apps/tactile-workbench.svg" || fail "no scalable icon"
# A PNG's width and height are the big-endian words at bytes 16 and 20.
png_size() { od -An -tu1 -j16 -N8 "$1" | awk '{ printf "%dx%d", $3*256+$4, $7*256+$8 }'; }
for size in 16 32 48 64 128 256; do
  png=$icons/${size}x${size}/apps/tactile-workbench.png
  [ -f "$png" ] || fail "no ${size}px icon"
  got=$(png_size "$png")
  [ "$got" = "${size}x${size}" ] || fail "icon in ${size}x${size} is $got"
done

# The installed programs, run from an unrelated folder with an empty settings home.
cd "$W/elsewhere"
export XDG_CONFIG_HOME=$W/config HOME=$W/config QT_QPA_PLATFORM=offscreen
"$P/bin/tactile" simulate --scene room1 --runs 1 --steps 300 --seed 3 --out-dir runs --prefix inst \
  --quiet >/dev/null || fail "installed tactile cannot simulate the built-in scene room1"
ls runs/inst*.csv >/dev/null 2>&1 || fail "simulate wrote no run file"
"$P/bin/tactile" import --db inst.db runs >/dev/null || fail "installed tactile cannot import"
LC_ALL=C "$P/bin/tactile-workbench" --db inst.db --screenshot shot.png || fail "installed workbench failed"
[ "$(png_size shot.png)" = "1600x1000" ] || fail "screenshot is $(png_size shot.png), not 1600x1000"

# The interface language follows the system locale.
LC_ALL=C.UTF-8 LANGUAGE= "$P/bin/tactile-workbench" --help >help_en.txt
grep -q 'tactile-navigation research desktop' help_en.txt || fail "English help not English"
LC_ALL=de_DE.UTF-8 LANGUAGE= "$P/bin/tactile-workbench" --help >help_de.txt
grep -q 'taktilen Navigation' help_de.txt || fail "German locale, help not German: $(head -3 help_de.txt)"
LC_ALL=zh_CN.UTF-8 LANGUAGE= "$P/bin/tactile-workbench" --help >help_zh.txt
grep -q '触觉导航' help_zh.txt || fail "Chinese locale, help not Chinese: $(head -3 help_zh.txt)"
echo "ok: installed into $P and ran from $W/elsewhere"
