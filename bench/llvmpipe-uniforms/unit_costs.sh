#!/bin/bash
# What a uniform-block read costs on llvmpipe (issue 14, session 10), from stubs of two
# passes on cube 640x480, map 512, processes alternating between stubs, $ROUNDS rounds:
#  1. classify.frag (a fragment shader over the image) with its main() replaced by a stub
#     that multiplies the pixel's position by the light's matrix, read from the light block
#     (a uniform block), from the flat input the vertex shader hands over
#     (FRAME_BLOCKS_FROM_VERTEX_STAGE, shaders/shared/frame.glsl), or a constant matrix;
#  2. trace.comp (a compute shader over the image) doing the same product four times in a
#     loop (the count read from the trace block at the top), with the matrix read from the
#     block inside the loop, or once at the top of main before any branch, or a constant
#     (trace.comp loads the blocks at the top, loadFrameBlocks; the stubs read the matrix
#     from lightBlock, the block itself);
#  3. four imageLoads per pixel at the same addresses of an RGBA32F array layer and of an
#     RGBA32F 2D image (the trace's N-buffer and bounds), against session 9's unit costs.
# Stage time minus the stub that only stores. From the repository root after building:
#   bash bench/llvmpipe-uniforms/unit_costs.sh
set -e
ROUNDS=${ROUNDS:-5}
OUT=${OUT:-bench/llvmpipe-uniforms/unit-costs.md}
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
# stub FILE NAME BODY [block]: a copy of shaders/ with FILE's main() replaced by BODY
# ("block": the fragment shader reads the uniform blocks, not the flat inputs).
stub() {
  cp -r shaders "$TMP/$2"
  python3 - "$TMP/$2/$1" "$3" "${4:-}" <<'PY'
import sys
path, body, block = sys.argv[1:4]
text = open(path).read()
if block:
    text = text.replace("#define FRAME_BLOCKS_FROM_VERTEX_STAGE", "// (block)")
open(path, "w").write(text[:text.index("void main() {")] + "void main() {\n  " + body + "\n}\n")
PY
}
FS_HEAD='ivec2 pixel = ivec2(gl_FragCoord.xy); vec4 p = imageLoad(wsPositionImage, pixel); if (p.w == 0.0) discard; maskOut = 1.0;'
stub classify.frag fs_store_only "$FS_HEAD zRangeOut = p;"
stub classify.frag fs_block_mat4 "$FS_HEAD zRangeOut = p + light.lightClipFromWorld * vec4(p.xyz, 1.0);" block
stub classify.frag fs_flat_mat4 "$FS_HEAD zRangeOut = p + light.lightClipFromWorld * vec4(p.xyz, 1.0);"
stub classify.frag fs_const_mat4 "$FS_HEAD zRangeOut = p + mat4(1.1, 1.2, 1.3, 1.4, 2.1, 2.2, 2.3, 2.4, 3.1, 3.2, 3.3, 3.4, 4.1, 4.2, 4.3, 4.4) * vec4(p.xyz, 1.0);"
CS_TAIL='imageStore(visibilityImage, pixel, vec4(acc.x));'
LOOP='for (int i = 0; i < traceBlock.config.x * 2; ++i) acc = 0.5 * (acc + m * acc);'
stub trace.comp cs_store_only "loadFrameBlocks(); ivec2 pixel = screenPixel(); if (pixel.x < 0) return; vec4 acc = vec4(pixel, 0, 1); $CS_TAIL"
stub trace.comp cs_block_in_loop "loadFrameBlocks(); ivec2 pixel = screenPixel(); if (pixel.x < 0) return; vec4 acc = vec4(pixel, 0, 1); for (int i = 0; i < traceBlock.config.x * 2; ++i) acc = 0.5 * (acc + lightBlock.lightClipFromWorld * acc); $CS_TAIL"
stub trace.comp cs_block_at_top "loadFrameBlocks(); mat4 m = lightBlock.lightClipFromWorld; ivec2 pixel = screenPixel(); if (pixel.x < 0) return; vec4 acc = vec4(pixel, 0, 1); $LOOP $CS_TAIL"
stub trace.comp cs_const "loadFrameBlocks(); mat4 m = mat4(1.1, 1.2, 1.3, 1.4, 2.1, 2.2, 2.3, 2.4, 3.1, 3.2, 3.3, 3.4, 4.1, 4.2, 4.3, 4.4); ivec2 pixel = screenPixel(); if (pixel.x < 0) return; vec4 acc = vec4(pixel, 0, 1); $LOOP $CS_TAIL"
READ_HEAD='loadFrameBlocks(); ivec2 pixel = screenPixel(); if (pixel.x < 0) return; ivec2 t = pixel & 255;'
stub trace.comp read_store_only "$READ_HEAD imageStore(visibilityImage, pixel, vec4(t.x));"
stub trace.comp read_array_layer "$READ_HEAD vec4 a = imageLoad(nbufferLevels, ivec3(t, 2)) + imageLoad(nbufferLevels, ivec3(t + 1, 2)) + imageLoad(nbufferLevels, ivec3(t.yx, 2)) + imageLoad(nbufferLevels, ivec3(t.yx + 1, 2)); imageStore(visibilityImage, pixel, a);"
stub trace.comp read_image2d "$READ_HEAD vec4 a = imageLoad(zRangeImage, t) + imageLoad(zRangeImage, t + 1) + imageLoad(zRangeImage, t.yx) + imageLoad(zRangeImage, t.yx + 1); imageStore(visibilityImage, pixel, a);"
FS_STUBS="fs_store_only fs_block_mat4 fs_flat_mat4 fs_const_mat4"
CS_STUBS="cs_store_only cs_block_in_loop cs_block_at_top cs_const"
READ_STUBS="read_store_only read_array_layer read_image2d"
for round in $(seq 1 "$ROUNDS"); do
  for s in $FS_STUBS; do
    PENUMBRA_SHADER_DIR="$TMP/$s" build/penumbra bench-compare --scene cube --width 640 --height 480 \
      --frames 10 --warmup 1 --set light.resolution=512 --set trace.hierarchy=nbuffer \
      --side "x:light.layers=two" --requested classify.mask --out "$TMP/$s-$round.md" >/dev/null
  done
  for s in $CS_STUBS $READ_STUBS; do
    PENUMBRA_SHADER_DIR="$TMP/$s" build/penumbra bench-compare --scene cube --width 640 --height 480 \
      --frames 10 --warmup 1 --set light.resolution=512 --set trace.hierarchy=nbuffer \
      --set trace.use_classification=false --side "x:trace.rays=2" --requested trace.visibility \
      --out "$TMP/$s-$round.md" >/dev/null
  done
done
{
  python3 bench/stub_table.py --dir "$TMP" --out "$TMP/fs.md" --column "classify ms" \
    --baseline fs_store_only --title "fragment stub (classify.frag, 640x480)" $FS_STUBS
  echo
  python3 bench/stub_table.py --dir "$TMP" --out "$TMP/cs.md" --column "trace ms" \
    --baseline cs_store_only --title "compute stub (trace.comp, 640x480, 4 products)" $CS_STUBS
  echo
  python3 bench/stub_table.py --dir "$TMP" --out "$TMP/reads.md" --column "trace ms" \
    --baseline read_store_only --title "4 reads per pixel, same addresses" --per 4 $READ_STUBS
} > "$OUT"
cat "$OUT"
