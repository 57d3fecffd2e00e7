#!/usr/bin/env bash
# The viewer's layout matrix (issue 18) as contact sheets: the default population, SYN005 at
# α = 45°, in reconstruct mode, at every window size × UI scale, one sheet per theme
# (docs/screenshots/layout_matrix_THEME.png). Not part of the build or CI: run it after a
# layout change and look at every cell.
#
#   bash docs/tools/layout_contact_sheet.sh [BUILD_DIR]   (default build/)
set -euo pipefail
cd "$(dirname "$0")/../.."
build=${1:-build}
viewer="$build/bin/eigenwalker"
[ -x "$viewer" ] || { echo "no viewer at $viewer: build first (make run)" >&2; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
g++ -std=c++20 -O2 -Wno-deprecated-enum-enum-conversion docs/tools/compose_contact_sheet.cpp -o "$work/compose" $(pkg-config --cflags --libs opencv4)
sizes="1024x768 1280x720 1366x768 1600x900 1920x1080 3840x2160"
scales="1 1.5 2"
for theme in dark light projector; do
  cells=()
  for size in $sizes; do
    for scale in $scales; do
      shot="$work/${theme}_${size}_${scale}.png"
      cat > "$work/script.json" <<JSON
[{"set_theme": "$theme"}, {"select_subject": "SYN005"}, {"set_angle": 45}, {"play": false},
 {"set_phase": 0.3}, {"wait_frames": 3}, {"screenshot": "$shot"}]
JSON
      EIGENWALKER_NO_SETTINGS=1 xvfb-run -a -s '-screen 0 3840x2160x24' "$viewer" --size "$size" \
        --ui-scale "$scale" --script "$work/script.json" > /dev/null 2> "$work/err.txt" ||
        { cat "$work/err.txt" >&2; exit 1; }
      cells+=("$shot" "$size, UI scale $scale")
    done
  done
  "$work/compose" "docs/screenshots/layout_matrix_$theme.png" 480 3 \
    "Layout matrix, $theme theme (SYN005, alpha = 45 deg)" "${cells[@]}"
  echo "wrote docs/screenshots/layout_matrix_$theme.png"
  cp "$work"/"${theme}"_*.png "${KEEP_CELLS:-$work}/" 2>/dev/null || true
done
