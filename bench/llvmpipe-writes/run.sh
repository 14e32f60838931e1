#!/bin/sh
# Issue 14, session 8: whole-image RGBA32F writes as fragment-shader passes, no shared
# memory or barriers in the list passes, close_risers over 2x2 blocks, the near layer
# gathered (bench/llvmpipe-writes/README.md). Before: commit $BEFORE (session 7's end), built
# from `git archive` into $TREE (C++ changed too, so the old binary runs with its own
# shaders); after: the current build. Three rounds, processes alternating before / after
# (the order swapped in even rounds), sides alternating frame by frame within a process. Run on
# a quiet machine from the repository root after building:
#   sh bench/llvmpipe-writes/run.sh && python3 bench/trace-records/summary.py bench/llvmpipe-writes
set -e  # ROUNDS=n for more rounds (default 3)
BEFORE=${BEFORE:-ff1fdb6}
OUT=${OUT:-bench/llvmpipe-writes}
TREE=${TREE:-/tmp/penumbra-$BEFORE}
if [ ! -x "$TREE/build/penumbra" ]; then
  mkdir -p "$TREE"
  git archive "$BEFORE" | tar -x -C "$TREE"
  cmake -S "$TREE" -B "$TREE/build" -DCMAKE_BUILD_TYPE=Release >/dev/null
  cmake --build "$TREE/build" -j2 --target penumbra >/dev/null
fi
cube() {  # $1 = before or after, $2 = round
  if [ "$1" = before ]; then bin=$TREE/build/penumbra shaders=$TREE/shaders; else bin=build/penumbra shaders=shaders; fi
  PENUMBRA_SHADER_DIR=$shaders $bin bench-compare --scene cube --width 640 --height 480 --frames 10 --warmup 1 \
    --set trace.search=hierarchical --set trace.rays=2 --set trace.deferred=true --set light.layers=two \
    --side "nbuffer_512:light.resolution=512;trace.hierarchy=nbuffer" \
    --side "minmax_512:light.resolution=512;trace.hierarchy=minmax" \
    --side "minmax_2048:light.resolution=2048;trace.hierarchy=minmax" \
    --requested composite.color --counters trace.raysSearched,trace.fetches --out "$OUT/cube-$1-r$2.md"
}
for round in $(seq 1 "${ROUNDS:-3}"); do
  if [ $((round % 2)) = 0 ]; then cube after $round; cube before $round; else cube before $round; cube after $round; fi
done
