#!/usr/bin/env bash
# Brings every translations/tactile_workbench_*.ts up to date with the workbench's sources: new
# strings are added as unfinished, strings no longer in the code are dropped. Run it after changing
# user-visible text in app/gui, translate what it added (Qt Linguist, or by hand in the .ts file),
# and run the translation test (ctest -R gui.translations), which fails on any unfinished entry.
#   scripts/translations.sh            update every .ts file
#   scripts/translations.sh LANG...    only these (e.g. de zh_CN); a new language gets a new file
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
lupdate=${LUPDATE:-}
if [ -z "$lupdate" ]; then
  for candidate in lupdate6 /usr/lib/qt6/bin/lupdate "$(command -v lupdate || true)"; do
    if [ -n "$candidate" ] && command -v "$candidate" >/dev/null 2>&1; then
      lupdate=$candidate
      break
    fi
  done
fi
if [ -z "$lupdate" ]; then
  echo "translations.sh: lupdate not found (Debian: apt-get install qt6-l10n-tools), or set LUPDATE" >&2
  exit 1
fi

# TACTILE_TS_DIR=DIR updates copies in DIR instead of translations/ (the test of the .ts files
# being current uses it).
ts_dir=${TACTILE_TS_DIR:-$root/translations}
ts_files=()
if [ $# -eq 0 ]; then
  ts_files=("$ts_dir"/tactile_workbench_*.ts)
else
  for lang in "$@"; do ts_files+=("$ts_dir/tactile_workbench_$lang.ts"); done
fi

# Every C++ source of the workbench (the CLI has no translated text). Without line numbers, so a
# .ts file changes only when a string does.
mapfile -t sources < <(find "$root/app/gui" -name '*.cpp' -o -name '*.h' | sort)
# English needs only the plural forms of the "%n" strings ("1 step", "2 steps"); the other
# languages need every string.
others=()
for ts in "${ts_files[@]}"; do
  if [ "$(basename "$ts")" = tactile_workbench_en.ts ]; then
    "$lupdate" -locations none -no-ui-lines -no-obsolete -silent -pluralonly -I "$root" \
      "${sources[@]}" -ts "$ts"
  else
    others+=("$ts")
  fi
done
if [ ${#others[@]} -gt 0 ]; then
  "$lupdate" -locations none -no-ui-lines -no-obsolete -silent -I "$root" "${sources[@]}" \
    -ts "${others[@]}"
fi
for ts in "${ts_files[@]}"; do
  left=$(grep -c 'type="unfinished"' "$ts" || true)
  echo "$(basename "$ts"): $left unfinished"
done
