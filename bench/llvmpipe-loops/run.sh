#!/bin/sh
# Issue 14, session 12: loops tested at the bottom and fewer branch sides in the shaders
# (bench/llvmpipe-loops/README.md). Only shaders changed since $BEFORE, so one binary (the
# current build) runs both sides: $BEFORE's shaders (`git archive`) and the working tree's.
# Cube 640x480, 2x2, hierarchical, deferred, two layers; $ROUNDS rounds, processes
# alternating before / after (the order swapped in even rounds), the three sides alternating
# frame by frame within a process, as bench/llvmpipe-writes/run.sh. From the repository root
# after building, on a quiet machine:
#   OUT=bench/llvmpipe-loops/run1 sh bench/llvmpipe-loops/run.sh && python3 bench/llvmpipe-loops/ratios.py bench/llvmpipe-loops/run1
set -e
BEFORE=${BEFORE:-c44319d}
OUT=${OUT:-bench/llvmpipe-loops/run1}
OLD=$(mktemp -d)
trap 'rm -rf "$OLD"' EXIT
git archive "$BEFORE" shaders | tar -x -C "$OLD"
mkdir -p "$OUT"
cube() {  # $1 = before or after, $2 = round
  if [ "$1" = before ]; then shaders=$OLD/shaders; else shaders=shaders; fi
  PENUMBRA_SHADER_DIR=$shaders build/penumbra bench-compare --scene cube --width 640 --height 480 --frames 10 --warmup 1 \
    --set trace.search=hierarchical --set trace.rays=2 --set trace.deferred=true --set light.layers=two \
    --side "nbuffer_512:light.resolution=512;trace.hierarchy=nbuffer" \
    --side "minmax_512:light.resolution=512;trace.hierarchy=minmax" \
    --side "minmax_2048:light.resolution=2048;trace.hierarchy=minmax" \
    --requested composite.color --counters trace.raysSearched,trace.fetches --out "$OUT/cube-$1-r$2.md" >/dev/null
}
for round in $(seq 1 "${ROUNDS:-5}"); do
  if [ $((round % 2)) = 0 ]; then cube after $round; cube before $round; else cube before $round; cube after $round; fi
done
