#!/bin/sh
# Regenerates what is written from the stage declarations (app/core/stage.h,
# stages/registry.cpp): the stage table in README.md (between the stage-table markers),
# docs/stage_graph.dot (`penumbra graph`) and docs/stage_graph.svg (that dot through
# Graphviz). `ctest -R StageDocs` fails while any of them is stale.
#   scripts/stage_docs.sh BUILD    (BUILD: the build folder holding `penumbra`)
# Nothing is half-written: each file is written beside itself and moved into place.
set -eu
if [ $# -ne 1 ]; then
  echo "usage: scripts/stage_docs.sh BUILD (the build folder holding penumbra)" >&2
  exit 2
fi
penumbra="$1/penumbra"
root=$(cd "$(dirname "$0")/.." && pwd)
readme="$root/README.md"
begin='<!-- stage-table:begin -->'
end='<!-- stage-table:end -->'
if [ ! -x "$penumbra" ]; then
  echo "scripts/stage_docs.sh: $penumbra is not an executable (build the penumbra target)" >&2
  exit 2
fi
if ! command -v dot >/dev/null; then
  echo "scripts/stage_docs.sh: dot (Graphviz) is not installed: scripts/setup.sh installs it" >&2
  exit 2
fi
if [ "$(grep -cxF "$begin" "$readme")" != 1 ] || [ "$(grep -cxF "$end" "$readme")" != 1 ]; then
  echo "scripts/stage_docs.sh: README.md needs the lines $begin and $end, once each" >&2
  exit 2
fi

work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
"$penumbra" graph --markdown >"$work/table.md"
"$penumbra" graph >"$work/stage_graph.dot"
dot -Tsvg "$work/stage_graph.dot" >"$work/stage_graph.svg"
# README.md: the lines before the begin marker, the marker, the table, then from the end
# marker on.
awk -v begin="$begin" -v end="$end" -v table="$work/table.md" '
  $0 == begin { print; while ((getline line < table) > 0) print line; skipping = 1; next }
  $0 == end { skipping = 0 }
  !skipping { print }' "$readme" >"$work/README.md"

cp "$work/README.md" "$readme.tmp" && mv "$readme.tmp" "$readme"
for file in stage_graph.dot stage_graph.svg; do
  cp "$work/$file" "$root/docs/$file.tmp" && mv "$root/docs/$file.tmp" "$root/docs/$file"
done
echo "wrote README.md (stage table), docs/stage_graph.dot, docs/stage_graph.svg"
