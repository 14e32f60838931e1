#!/bin/sh
# Issue 14, trace.hierarchy=auto: where the min-max mipmap overtakes the N-buffer (the
# crossovers behind kNBufferTexelLevelsPerEyePixel in stages/monte_carlo/trace.cpp), and
# what `auto` gives on the window's default view of each built-in scene. Run on a quiet
# machine from the repository root after building: sh bench/hierarchy-auto/run.sh
# Session 7 (the crossover lower, below the old sizes): OUT=bench/hierarchy-auto/s7
#   CUBE640="256 384 512 640" CUBE320="192 256 384" SPHERES="128 192 256" DRAGON="256 384 512"
set -e
P=build/penumbra
OUT=${OUT:-bench/hierarchy-auto}
COMMON="--set trace.search=hierarchical --set trace.rays=2 --set trace.deferred=true --set light.layers=two --requested composite.color --counters classify.penumbra,trace.raysSearched"
sides() {  # map sizes -> an nbuffer and a minmax side for each
  for m in "$@"; do
    printf -- "--side nbuffer_%s:light.resolution=%s;trace.hierarchy=nbuffer " "$m" "$m"
    printf -- "--side minmax_%s:light.resolution=%s;trace.hierarchy=minmax " "$m" "$m"
  done
}
# 1. Crossovers: frames alternate between the sides, so the ratios hold under drift.
$P bench-compare --scene cube --width 640 --height 480 --frames 6 --warmup 1 $COMMON $(sides ${CUBE640:-512 640 768 1024}) --out $OUT/crossover-cube-640x480.md
$P bench-compare --scene cube --width 320 --height 240 --frames 8 --warmup 1 $COMMON $(sides ${CUBE320:-256 384 512}) --out $OUT/crossover-cube-320x240.md
$P bench-compare --scene spheres --width 128 --height 96 --frames 12 --warmup 1 $COMMON $(sides ${SPHERES:-128 256 384}) --out $OUT/crossover-spheres-128x96.md
$P bench-compare --scene dragon --width 640 --height 480 --frames 5 --warmup 1 $COMMON $(sides ${DRAGON:-512 640 768}) --out $OUT/crossover-dragon-640x480.md
# 2. The window's default view (616x665, every parameter at its default): auto against a
#    hand-set N-buffer.
for scene in cube spheres engine plate dragon; do
  $P bench-compare --scene $scene --width 616 --height 665 --frames 5 --warmup 1 \
    --side "auto:trace.hierarchy=auto" --side "nbuffer:trace.hierarchy=nbuffer" \
    --requested composite.color --counters auto.resolution,classify.penumbra \
    --out $OUT/default-$scene.md
done
