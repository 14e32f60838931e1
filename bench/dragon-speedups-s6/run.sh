#!/bin/sh
# Issue 14 item 5 again (session 6, after the trace was specialized per search and hierarchy):
# hierarchical (two and three layers) against linear/binary (three layers, the thesis's) on
# the dragon, maps 512 / 1024 / 2048, 2x2 and 3x3 rays; whole frame, trace stage, fetches per
# searched ray and the trace's error against the reference. The same command as
# bench/dragon-speedups.md (session 3), with 5 timed frames. Run on a quiet machine from the
# repository root after building: sh bench/dragon-speedups-s6/run.sh
set -e
P=build/penumbra
OUT=${OUT:-bench/dragon-speedups-s6}
for map in 512 1024 2048; do
  for rays in 2 3; do
    $P bench-compare --scene dragon --width 512 --height 384 --frames 5 --warmup 1 \
      --set light.resolution=$map --set trace.rays=$rays --set trace.deferred=true --set trace.hierarchy=nbuffer \
      --side "hierarchical_2L:trace.search=hierarchical;light.layers=two" \
      --side "hierarchical_3L:trace.search=hierarchical;light.layers=three" \
      --side "linear_binary_3L:trace.search=linear_binary;light.layers=three" \
      --requested filter.visibility --counters trace.raysSearched,trace.fetches,classify.penumbra \
      --error-of trace --out $OUT/map$map-rays$rays.md
  done
done
