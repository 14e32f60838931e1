# Sourced by bench/trace-records/run.sh and bench/trace-variants/run.sh: the current binary
# run with two sets of shaders swapped in with PENUMBRA_SHADER_DIR, $TMP/before and
# $TMP/after (the shaders of commits $BEFORE and $AFTER), on cube and dragon; each call
# writes one bench-compare file to $OUT. The caller sets BEFORE, AFTER and OUT and
# alternates the calls. Only shaders/ is swapped: the layout headers in stages/ are the
# binary's own on both sides (docs/design.md#layouts), and both trees must use the layout of
# shaders/<family>/<stage>/ the binary loads.
set -e
P=$(pwd)/build/penumbra
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
git archive "$BEFORE" shaders | tar -x -C "$TMP" && mv "$TMP/shaders" "$TMP/before"
git archive "$AFTER" shaders | tar -x -C "$TMP" && mv "$TMP/shaders" "$TMP/after"
cube() {  # $1 = shader dir name under $TMP, $2 = round
  PENUMBRA_SHADER_DIR="$TMP/$1" $P bench-compare --scene cube --width 640 --height 480 --frames 8 --warmup 1 \
    --set trace.search=hierarchical --set trace.rays=2 --set trace.deferred=true --set light.layers=two \
    --side "nbuffer_512:light.resolution=512;trace.hierarchy=nbuffer" \
    --side "minmax_2048:light.resolution=2048;trace.hierarchy=minmax" \
    --requested composite.color --counters trace.raysSearched,trace.fetches --out "$OUT/cube-$1-r$2.md"
}
dragon() {  # $1 = shader dir name under $TMP, $2 = map, $3 = round
  PENUMBRA_SHADER_DIR="$TMP/$1" $P bench-compare --scene dragon --width 512 --height 384 --frames 9 --warmup 1 \
    --set light.resolution=$2 --set trace.rays=2 --set trace.deferred=true --set trace.hierarchy=nbuffer \
    --side "hierarchical_2L:trace.search=hierarchical;light.layers=two" \
    --side "linear_binary_3L:trace.search=linear_binary;light.layers=three" \
    --requested filter.visibility --counters trace.raysSearched,trace.fetches --out "$OUT/dragon$2-$1-r$3.md"
}
before_after_rounds() {  # three rounds, processes alternating before / after
  for round in 1 2 3; do
    for side in before after; do
      cube $side $round
      dragon $side 1024 $round
      dragon $side 2048 $round
    done
  done
}
