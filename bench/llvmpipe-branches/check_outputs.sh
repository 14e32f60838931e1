#!/bin/bash
# The "same outputs" check of bench/llvmpipe-branches/README.md: the current binary exports
# every stage output with the shaders of $BEFORE and of $AFTER (PENUMBRA_SHADER_DIR) on 50
# cases (five scenes x two hierarchies x five combinations of map, layers, search and
# deferred / forward, 160x120) and the engine at 320x240, map 1024 (where a gather on the
# near layer once changed classification); every EXR is compared at zero tolerance and the
# counters of run.json must be equal. Prints the differing files; exit 1 if any differ.
# From the repository root after building: bash bench/llvmpipe-branches/check_outputs.sh
# (12 min on the 2 cores). Where the C++ changed too (session 8), BEFORE_BIN is a binary
# built from $BEFORE (e.g. by bench/llvmpipe-writes/run.sh), which the before side runs:
#   BEFORE=ff1fdb6 BEFORE_BIN=/tmp/penumbra-ff1fdb6/build/penumbra bash bench/llvmpipe-branches/check_outputs.sh
BEFORE=${BEFORE:-e6644b0} AFTER=${AFTER:-HEAD}
P=$(pwd)/build/penumbra
BEFORE_BIN=${BEFORE_BIN:-$P}
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
for side in before after; do
  commit=$([ $side = before ] && echo "$BEFORE" || echo "$AFTER")
  git archive "$commit" shaders | tar -x -C "$TMP" && mv "$TMP/shaders" "$TMP/$side"
done
exrs=0 differ=0 cases=0
compare() {  # $1 = case name; export_case has written $TMP/out/{before,after}/$1
  cases=$((cases + 1))
  for exr in "$TMP/out/before/$1"/*.exr; do
    exrs=$((exrs + 1))
    if ! idiff -fail 0 -warn 0 "$exr" "$TMP/out/after/$1/$(basename "$exr")" >/dev/null; then
      echo "differs: $1 $(basename "$exr")"; differ=$((differ + 1))
    fi
  done
  counters() { python3 -c "import json, sys; print(json.load(open(sys.argv[1]))['counters'])" "$1"; }
  if [ "$(counters "$TMP/out/before/$1/run.json")" != "$(counters "$TMP/out/after/$1/run.json")" ]; then
    echo "counters differ: $1"; differ=$((differ + 1))
  fi
  rm -rf "$TMP/out/before/$1" "$TMP/out/after/$1"
}
export_case() {  # $1 = case name, then export options
  name=$1; shift
  for side in before after; do
    bin=$P; [ $side = before ] && bin=$BEFORE_BIN
    PENUMBRA_SHADER_DIR="$TMP/$side" $bin export "$@" --out "$TMP/out/$side/$name" >/dev/null 2>&1 ||
      { echo "export failed: $name ($side)"; differ=$((differ + 1)); }
  done
  compare "$name"
}
for scene in cube plate spheres engine dragon; do
  for hierarchy in nbuffer minmax; do
    for variant in 300:two:hierarchical:true 256:three:linear_binary:true 1024:three:hierarchical:true \
                   256:two:linear:false 300:one:hierarchical:true; do
      IFS=: read -r map layers search deferred <<< "$variant"
      export_case "$scene-$hierarchy-$map-$layers-$search-$deferred" --scene $scene --width 160 --height 120 \
        --set light.resolution=$map --set trace.hierarchy=$hierarchy --set trace.rays=3 \
        --set light.layers=$layers --set trace.search=$search --set trace.deferred=$deferred
    done
  done
done
export_case engine-320x240-1024 --scene engine --width 320 --height 240 --set light.resolution=1024
echo "$cases cases, $exrs EXRs compared, $differ differences"
[ "$differ" = 0 ]
