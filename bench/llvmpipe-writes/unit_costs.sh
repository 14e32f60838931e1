#!/bin/bash
# What one operation per pixel costs a compute pass on llvmpipe (issue 14, session 8): the
# classify pass of commit $BEFORE (session 7's end, still a compute shader with an R32F and
# an RGBA32F image, RGBA32F and R32F textures and a storage buffer bound) with its main()
# replaced by a stub doing one kind of operation per pixel of cube 640x480; the stage's time
# minus the empty stub's is the operation's cost over 307,200 pixels. Processes alternate
# between the stubs, $ROUNDS rounds; medians. Needs the before tree of run.sh ($TREE, built
# there). From the repository root: bash bench/llvmpipe-writes/unit_costs.sh
set -e
BEFORE=${BEFORE:-ff1fdb6} ROUNDS=${ROUNDS:-5}
TREE=${TREE:-/tmp/penumbra-$BEFORE}
OUT=${OUT:-bench/llvmpipe-writes/unit-costs.md}
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
declare -A STUBS=(
  [empty]='if (pixel.x == -5) imageStore(maskImage, pixel, vec4(1.0));'
  [store_r32f]='if (pixel.x >= 0) imageStore(maskImage, pixel, vec4(float(pixel.x)));'
  [store_rgba32f]='if (pixel.x >= 0) imageStore(zRangeImage, pixel, vec4(float(pixel.x)));'
  [store_ssbo]='if (pixel.x >= 0) tracedPixels[uint(pixel.y * 640 + pixel.x)] = uint(pixel.x);'
  [fetch4_rgba32f_store_ssbo]='if (pixel.x >= 0) { vec4 a = texelFetch(wsPositionTexture, pixel, 0) + texelFetch(wsNormalTexture, pixel, 0) + texelFetch(wsPositionTexture, pixel.yx, 0) + texelFetch(wsNormalTexture, pixel.yx, 0); tracedPixels[uint(pixel.y * 640 + pixel.x)] = floatBitsToUint(a.x + a.y + a.z + a.w); }'
  [fetch4_r32f_store_ssbo]='if (pixel.x >= 0) { ivec2 t = pixel & 511; float a = texelFetch(nearLayer, t, 0).r + texelFetch(farLayer, t, 0).r + texelFetch(nearLayer, t.yx, 0).r + texelFetch(farLayer, t.yx, 0).r; tracedPixels[uint(pixel.y * 640 + pixel.x)] = floatBitsToUint(a); }'
)
for stub in "${!STUBS[@]}"; do
  cp -r "$TREE/shaders" "$TMP/$stub"
  python3 - "$TMP/$stub/classify.comp" "${STUBS[$stub]}" <<'PY'
import sys
path, body = sys.argv[1], sys.argv[2]
text = open(path).read()
open(path, "w").write(text[:text.index("void main() {")] +
                      "void main() {\n  ivec2 pixel = screenPixel();\n  " + body + "\n}\n")
PY
done
for round in $(seq 1 "$ROUNDS"); do
  for stub in "${!STUBS[@]}"; do
    PENUMBRA_SHADER_DIR="$TMP/$stub" "$TREE/build/penumbra" bench-compare --scene cube --width 640 \
      --height 480 --frames 10 --warmup 1 --set light.resolution=512 --set trace.hierarchy=nbuffer \
      --side "x:trace.rays=2" --requested classify.mask --out "$TMP/$stub-$round.md" >/dev/null
  done
done
python3 bench/stub_table.py --dir "$TMP" --out "$OUT" --column "classify ms" --baseline empty \
  --title "stub (one per pixel of 640x480)" "${!STUBS[@]}"
