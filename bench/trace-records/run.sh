#!/bin/sh
# Issue 14, session 6: the trace with its step records compiled out (TRACE_RECORDING 0 in
# shaders/shared/trace_ray.glsl), against the shaders before it (commit f53a80a: the records'
# branches compiled in, checked at run time), and what the rest of the trace costs once the
# search is taken out. Both sides run on the same binary: `before` swaps in the old shaders
# with PENUMBRA_SHADER_DIR (they ignore the TRACE_RECORDING define). Processes alternate
# before / after, three rounds; within a process the sides alternate frame by frame.
# Run on a quiet machine from the repository root after building:
#   sh bench/trace-records/run.sh
set -e
P=$(pwd)/build/penumbra
OUT=${OUT:-bench/trace-records}
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
git archive f53a80a shaders | tar -x -C "$TMP" && mv "$TMP/shaders" "$TMP/before"
cp -r shaders "$TMP/after"
# Ablations of the current shaders (timing only; their images are wrong on purpose):
#  no_search: every searched ray gets a constant answer instead of its search;
#  no_early_outs: as no_search, and the inside and region early outs are skipped too;
#  empty: every invocation returns at once (dispatch, clears, the list).
python3 - "$TMP" <<'PY'
import shutil, sys
tmp = sys.argv[1]
def variant(name, edits):
    shutil.copytree(f"{tmp}/after", f"{tmp}/{name}")
    for path, old, new in edits:
        p = f"{tmp}/{name}/{path}"
        text = open(p).read()
        assert old in text, (name, old)
        open(p, "w").write(text.replace(old, new))
no_search = ("shared/trace_pixel.glsl", "    bool blocked = search == SEARCH_HIERARCHICAL",
             "    bool blocked = (gIterations & 1u) != 0u; if (false) blocked = search == SEARCH_HIERARCHICAL")
variant("no_search", [no_search])
variant("no_early_outs", [no_search,
    ("shared/trace_pixel.glsl", "    if (trace.switches.y != 0 && !endKept", "    if (false && !endKept"),
    ("shared/trace_pixel.glsl", "(trace.switches.z != 0 && regionIsEmpty", "(false && regionIsEmpty"),
    ("shared/trace_pixel.glsl", "    if (trace.switches.y != 0 && endKept &&", "    if (false && endKept &&")])
variant("empty", [("trace.comp", "  if (pixel.x < 0) return;\n", "  if (pixel.x < 0 || trace.config.x > 0) return;\n")])
PY
cube() {  # $1 = shader dir name, $2 = round
  PENUMBRA_SHADER_DIR="$TMP/$1" $P bench-compare --scene cube --width 640 --height 480 --frames 8 --warmup 1 \
    --set trace.search=hierarchical --set trace.rays=2 --set trace.deferred=true --set light.layers=two \
    --side "nbuffer_512:light.resolution=512;trace.hierarchy=nbuffer" \
    --side "minmax_2048:light.resolution=2048;trace.hierarchy=minmax" \
    --requested composite.color --counters trace.raysSearched,trace.fetches --out "$OUT/cube-$1-r$2.md"
}
dragon() {  # $1 = shader dir name, $2 = map, $3 = round
  PENUMBRA_SHADER_DIR="$TMP/$1" $P bench-compare --scene dragon --width 512 --height 384 --frames 9 --warmup 1 \
    --set light.resolution=$2 --set trace.rays=2 --set trace.deferred=true --set trace.hierarchy=nbuffer \
    --side "hierarchical_2L:trace.search=hierarchical;light.layers=two" \
    --side "linear_binary_3L:trace.search=linear_binary;light.layers=three" \
    --requested filter.visibility --counters trace.raysSearched,trace.fetches --out "$OUT/dragon$2-$1-r$3.md"
}
for round in 1 2 3; do
  for side in before after; do
    cube $side $round
    dragon $side 1024 $round
    dragon $side 2048 $round
  done
done
for round in 1 2; do
  for side in after no_search no_early_outs empty; do
    dragon $side 2048 a$round
  done
done
