#!/bin/bash
# What classification's two clears cost on llvmpipe (issue 14, session 11): classify.frag
# with its main() replaced by a stub that discards the background and writes constants
# elsewhere, so the stage is its fixed part (the clears, a draw over the image, the list
# pass). Run by the binary of $BEFORE (glClearTexImage on both targets, then the draw) and
# by the current one (the clears are clears of the framebuffer the draw renders into,
# ScreenTriangle::clearAndDraw); and both with a stub that writes every pixel without
# reading anything (the clears still run, though the draw covers them all). Processes
# alternate, $ROUNDS rounds, cube 640x480, map 512. From the repository root after building
# the current tree and $BEFORE (bench/llvmpipe-writes/run.sh builds it into $TREE):
#   bash bench/llvmpipe-fixed-costs/unit_costs.sh
set -e
ROUNDS=${ROUNDS:-5}
BEFORE=${BEFORE:-117b4e4}
TREE=${TREE:-/tmp/penumbra-$BEFORE}
OUT=${OUT:-bench/llvmpipe-fixed-costs/unit-costs.md}
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
# stub TREE NAME BODY: a copy of TREE's shaders/ with classify.frag's main() replaced by BODY.
stub() {
  cp -r "$1/shaders" "$TMP/$2"
  python3 - "$TMP/$2/classify.frag" "$3" <<'PY'
import sys
path, body = sys.argv[1:3]
text = open(path).read()
open(path, "w").write(text[:text.index("void main() {")] + "void main() {\n  " + body + "\n}\n")
PY
}
DISCARD='if (imageLoad(wsPositionImage, ivec2(gl_FragCoord.xy)).w == 0.0) discard; maskOut = 1.0; zRangeOut = vec4(0.5);'
stub "$TREE" before_clear_tex_image "$DISCARD"
stub . after_clear_in_draw "$DISCARD"
stub "$TREE" before_no_discard 'maskOut = 1.0; zRangeOut = vec4(0.5);'
stub . after_no_discard 'maskOut = 1.0; zRangeOut = vec4(0.5);'
STUBS="before_clear_tex_image after_clear_in_draw before_no_discard after_no_discard"
for round in $(seq 1 "$ROUNDS"); do
  for s in $STUBS; do
    bin=build/penumbra
    case $s in before_*) bin=$TREE/build/penumbra ;; esac
    PENUMBRA_SHADER_DIR="$TMP/$s" $bin bench-compare --scene cube --width 640 --height 480 \
      --frames 10 --warmup 1 --set light.resolution=512 --set trace.hierarchy=nbuffer \
      --side "x:light.layers=two" --requested classify.mask --out "$TMP/$s-$round.md" >/dev/null
  done
done
python3 bench/stub_table.py --dir "$TMP" --out "$OUT" --column "classify ms" \
  --baseline after_clear_in_draw --title "classification stub (640x480)" $STUBS
