#!/bin/bash
# What one kind of read costs a compute pass on llvmpipe (issue 14, session 9): the trace
# pass (trace.comp, over every pixel: trace.use_classification=false) with its main()
# replaced by a stub doing 4 reads of one kind per pixel of cube 640x480 and storing their
# sum; the stage's time minus the stub that only stores is the 4 reads' cost over 307,200
# pixels. The trace binds the G-buffer and the near layer (a depth texture) to texture
# units, and the far layer (R32F), the N-buffer (an RGBA32F array), the mask (R32F) and
# the bounds (RGBA32F) to image units. Processes alternate between the stubs, $ROUNDS
# rounds; medians. From the repository root after building:
#   bash bench/llvmpipe-reads/unit_costs.sh
set -e
ROUNDS=${ROUNDS:-5}
OUT=${OUT:-bench/llvmpipe-reads/unit-costs.md}
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
declare -A STUBS=(
  [store_only]='float v = float(pixel.x);'
  [texelFetch_rgba32f]='vec4 a = texelFetch(wsPositionTexture, pixel, 0) + texelFetch(wsNormalTexture, pixel, 0) + texelFetch(wsPositionTexture, pixel.yx, 0) + texelFetch(wsNormalTexture, pixel.yx, 0); float v = a.x + a.y + a.z + a.w;'
  [texelFetch_depth]='ivec2 t = pixel & 511; float v = texelFetch(nearLayer, t, 0).r + texelFetch(nearLayer, t + 1, 0).r + texelFetch(nearLayer, t.yx, 0).r + texelFetch(nearLayer, t.yx + 1, 0).r;'
  [imageLoad_rgba32f]='vec4 a = imageLoad(zRangeImage, pixel) + imageLoad(zRangeImage, pixel + 1) + imageLoad(zRangeImage, pixel.yx) + imageLoad(zRangeImage, pixel.yx + 1); float v = a.x + a.y + a.z + a.w;'
  [imageLoad_rgba32f_array]='ivec2 t = pixel & 511; vec4 a = imageLoad(nbufferLevels, ivec3(t, 2)) + imageLoad(nbufferLevels, ivec3(t.yx, 3)) + imageLoad(nbufferLevels, ivec3(t, 4)) + imageLoad(nbufferLevels, ivec3(t.yx, 5)); float v = a.x + a.y + a.z + a.w;'
  [imageLoad_r32f]='ivec2 t = pixel & 511; float v = imageLoad(farLayer, t).r + imageLoad(classMask, pixel).r + imageLoad(farLayer, t.yx).r + imageLoad(classMask, pixel.yx).r;'
)
for stub in "${!STUBS[@]}"; do
  cp -r shaders "$TMP/$stub"
  python3 - "$TMP/$stub/trace.comp" "${STUBS[$stub]}" <<'PY'
import sys
path, body = sys.argv[1], sys.argv[2]
text = open(path).read()
open(path, "w").write(text[:text.index("void main() {")] +
                      "void main() {\n  ivec2 pixel = screenPixel();\n  if (pixel.x < 0) return;\n  " +
                      body + "\n  imageStore(visibilityImage, pixel, vec4(v));\n}\n")
PY
done
for round in $(seq 1 "$ROUNDS"); do
  for stub in "${!STUBS[@]}"; do
    PENUMBRA_SHADER_DIR="$TMP/$stub" build/penumbra bench-compare --scene cube --width 640 \
      --height 480 --frames 10 --warmup 1 --set light.resolution=512 --set trace.hierarchy=nbuffer \
      --set trace.use_classification=false --side "x:trace.rays=2" --requested trace.visibility \
      --out "$TMP/$stub-$round.md" >/dev/null
  done
done
python3 bench/stub_table.py --dir "$TMP" --out "$OUT" --column "trace ms" --baseline store_only \
  --title "stub: 4 reads per pixel of 640x480" --per 4 "${!STUBS[@]}"
