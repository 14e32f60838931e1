#!/usr/bin/env bash
# The README's two pictures (`make readme-figures`), regenerated from the program itself:
#   docs/images/window.png   the window (1280 x 800): the cube's filtered soft shadow beside
#                            its classification (scripts/readme_window.json)
#   docs/images/methods.png  every shadow method side by side on the same scene with its
#                            time and error: the figure sheet of lessons/all_methods.json
# Usage: scripts/readme_figures.sh [BUILD_DIR]  (default: build; needs xvfb-run without a display)
set -euo pipefail
build=${1:-build}
root=$(cd "$(dirname "$0")/.." && pwd)
penumbra="$root/$build/penumbra"
[ -x "$penumbra" ] || { echo "readme_figures: no $penumbra; run make build first" >&2; exit 2; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
display=()
[ -n "${DISPLAY:-}" ] || display=(xvfb-run -a -s '-screen 0 1280x800x24')
"${display[@]}" "$penumbra" --width 1280 --height 800 --script "$root/scripts/readme_window.json" --export "$work/window"
"${display[@]}" "$penumbra" lesson "$root/lessons/all_methods.json" --export "$work/methods"
mkdir -p "$root/docs/images"
cp "$work/window/window.png" "$root/docs/images/window.png"
cp "$work/methods/figure_sheet.png" "$root/docs/images/methods.png"
cp "$work/methods/lesson.md" "$root/docs/images/methods.md"
echo "wrote docs/images/window.png, docs/images/methods.png (and methods.md, its numbers)"
