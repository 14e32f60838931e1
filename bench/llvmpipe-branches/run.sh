#!/bin/sh
# Issue 14, session 7: shaders written for llvmpipe's lockstep lanes (both sides of every
# branch run, also of one on a uniform; a loop runs while any lane is in it): the trace
# specialized per layer count (TRACE_LAYERS), classify's min-max cells in two loops and its
# second pass as a loop, the min-max level 1 and the close_risers pass without branches and
# with far-layer gathers. Before: the shaders of commit $BEFORE; after: $AFTER; both on the
# current binary with PENUMBRA_SHADER_DIR (the old shaders ignore the new defines and do
# what they did). Processes alternate before / after, three rounds; sides alternate frame by
# frame within a process. Run on a quiet machine from the repository root after building:
#   sh bench/llvmpipe-branches/run.sh && python3 bench/trace-records/summary.py bench/llvmpipe-branches
BEFORE=${BEFORE:-e6644b0} AFTER=${AFTER:-HEAD}
OUT=${OUT:-bench/llvmpipe-branches}
. scripts/ab_shaders.sh
cube() {  # ab_shaders.sh's, with the min-max mipmap at map 512 as a third side
  PENUMBRA_SHADER_DIR="$TMP/$1" $P bench-compare --scene cube --width 640 --height 480 --frames 8 --warmup 1 \
    --set trace.search=hierarchical --set trace.rays=2 --set trace.deferred=true --set light.layers=two \
    --side "nbuffer_512:light.resolution=512;trace.hierarchy=nbuffer" \
    --side "minmax_512:light.resolution=512;trace.hierarchy=minmax" \
    --side "minmax_2048:light.resolution=2048;trace.hierarchy=minmax" \
    --requested composite.color --counters trace.raysSearched,trace.fetches --out "$OUT/cube-$1-r$2.md"
}
before_after_rounds
