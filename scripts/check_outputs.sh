#!/bin/bash
# The zero-tolerance output check: every stage output (EXR) and the counters of run.json of
# many cases, exported by two builds, must be identical. The before side runs $BEFORE_BIN
# with the shaders of commit $BEFORE, the after side ./build/penumbra with the shaders of
# $AFTER (both through PENUMBRA_SHADER_DIR; a layout header in stages/ is each binary's own,
# from its source tree); the cases: five scenes x two hierarchies x five
# combinations of map, layers, search and deferred / forward at 160x120, and the engine at
# 320x240, map 1024 (QUICK=1: the cube and the engine only). Counters compared: those the
# before side writes (counters only the after side has are listed, not counted as
# differences). Prints the differing files; exit 1 if any differ.
# From the repository root after building (12 min on 2 cores; QUICK=1 about 3):
#   BEFORE=main BEFORE_BIN=/tmp/penumbra-main/build/penumbra bash scripts/check_outputs.sh
# (build the before side from `git archive $BEFORE | tar -x -C /tmp/penumbra-main`).
BEFORE=${BEFORE:-main} AFTER=${AFTER:-HEAD}
# `auto` with the constants on both sides, not a measurement of this machine's load
# (docs/decisions/071-auto-calibrated-per-renderer.md).
export PENUMBRA_CALIBRATION=fallback
P=$(pwd)/build/penumbra
BEFORE_BIN=${BEFORE_BIN:-$P}
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
for side in before after; do
  commit=$([ $side = before ] && echo "$BEFORE" || echo "$AFTER")
  if [ "$commit" = WORKTREE ]; then cp -r shaders "$TMP/$side"; continue; fi
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
  if ! python3 - "$TMP/out/before/$1/run.json" "$TMP/out/after/$1/run.json" "$1" <<'PY'; then
import json, sys
before, after = (json.load(open(p))['counters'] for p in sys.argv[1:3])
changed = [k for k in before if before[k] != after.get(k)]
for k in changed: print(f"counter differs: {sys.argv[3]} {k}: {before[k]} -> {after.get(k)}")
new = sorted(set(after) - set(before))
if new and sys.argv[3].startswith("cube-nbuffer-300"): print("new counters: " + ", ".join(new))
sys.exit(1 if changed else 0)
PY
    differ=$((differ + 1))
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
scenes="cube plate spheres engine dragon"
[ "${QUICK:-0}" = 1 ] && scenes="cube engine"
for scene in $scenes; do
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
