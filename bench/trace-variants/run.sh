#!/bin/sh
# Issue 14, session 6: the trace and classify programs specialized per hierarchy and search
# (TRACE_HIERARCHY, TRACE_SEARCH in shaders/shared/trace_ray.glsl; CLASSIFY_OVER_MINMAX in
# shaders/classify.comp), against the shaders before it (commit cf71058: every hierarchy and
# search compiled into one program, chosen at run time; the step records already compiled
# out). Both sides run on the same binary: `before` swaps in the old shaders with
# PENUMBRA_SHADER_DIR (they ignore the new defines and read the same parameter block).
# Processes alternate before / after, three rounds; within a process the sides alternate
# frame by frame. Run on a quiet machine from the repository root after building:
#   sh bench/trace-variants/run.sh && python3 bench/trace-records/summary.py bench/trace-variants
set -e
P=$(pwd)/build/penumbra
OUT=${OUT:-bench/trace-variants}
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
git archive cf71058 shaders | tar -x -C "$TMP" && mv "$TMP/shaders" "$TMP/before"
cp -r shaders "$TMP/after"
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
