#!/bin/bash
# Where the target configuration's time goes on llvmpipe, by stubs (issue 14, session 12).
# Copies of the shaders of $SHADERS (default c44319d, session 11's end, where the stubs were
# cut; the binary's C++ is the same since) with parts of the trace or of the N-buffer's
# level pass cut out, run in turn ($ROUNDS rounds, processes alternating), cube 640x480, map
# 512, 2x2, hierarchical, deferred, two layers, `--requested composite.color` (the N-buffer
# writes its distinct texels only). Outputs of a stub are wrong by design; only the times
# are read. From the repository root after building:
#   bash bench/llvmpipe-floor/stubs.sh
# Trace stubs, each cutting more than the one before (shaders/shared/trace_pixel.glsl):
#   trace_without_search       the search replaced by a test of sStart and sEnd (kept live)
#   trace_without_early_outs   and the inside and region early outs removed
#   trace_without_ray_setup    and the bias, the ray, its clipping and shortening removed
#   trace_without_rays         the ray loop never entered (its body still runs once, masked)
# N-buffer stubs (shaders/nbuffer_level.frag, levels 2 and up):
#   nbuffer_two_reads          two image loads per texel instead of four
#   nbuffer_constant           no reads: each texel written with a constant
set -e
ROUNDS=${ROUNDS:-5}
OUT=${OUT:-bench/llvmpipe-floor}
SHADERS=${SHADERS:-c44319d}
TMP=$(mktemp -d)
trap 'rm -rf "$TMP"' EXIT
git archive "$SHADERS" shaders | tar -x -C "$TMP"
variant() {  # NAME: a copy of $SHADERS's shaders/ with NAME's cuts
  cp -r "$TMP/shaders" "$TMP/$1"
  python3 - "$TMP/$1" "$1" <<'PY'
import sys
root, name = sys.argv[1:3]
def cut(path, old, new):
    text = open(f"{root}/{path}").read()
    assert old in text, (name, old)
    open(f"{root}/{path}", "w").write(text.replace(old, new, 1))
def between(path, start, end, new):  # replaces [start, end) of the file by new
    text = open(f"{root}/{path}").read()
    i, j = text.index(start), text.index(end)
    open(f"{root}/{path}", "w").write(text[:i] + new + text[j:])
pixel = "shared/trace_pixel.glsl"
steps = ["trace_without_search", "trace_without_early_outs", "trace_without_ray_setup"]
if name in steps:
    between(pixel, "    bool blocked = search == SEARCH_HIERARCHICAL", "    if (!blocked) ++unblocked;",
            "    bool blocked = sEnd < sStart + 0.5;\n")
if name in steps[1:]:
    between(pixel, "    bool endKept =", "    // 5. The search.", "")
if name in steps[2:]:
    between(pixel, "    float bias = light.bias.x;", "    if (!blocked) ++unblocked;",
            "    bool blocked = direction.x > 0.3;\n")
if name == "trace_without_rays":
    cut(pixel, "for (int i = 0; i < rayCount; ++i) {", "for (int i = 0; i < rayCount && receiverZ < -1e30; ++i) {")
level = "nbuffer_level.frag"
if name == "nbuffer_two_reads":
    cut(level, "vec4 c = imageLoad(finer, ivec2(first.x, second.y));", "vec4 c = a;")
    cut(level, "vec4 d = imageLoad(finer, second);", "vec4 d = b;")
if name == "nbuffer_constant":
    between(level, "  ivec2 size = imageSize(finer);", "}\n", "  coarser = vec4(gl_FragCoord.xy, float(uLevel), 0.0);\n")
PY
}
TRACE="base trace_without_search trace_without_early_outs trace_without_ray_setup trace_without_rays"
NBUFFER="nbuffer_two_reads nbuffer_constant"
for v in $TRACE $NBUFFER; do variant $v; done
for round in $(seq 1 "$ROUNDS"); do
  for v in $TRACE $NBUFFER; do
    PENUMBRA_SHADER_DIR="$TMP/$v" build/penumbra bench-compare --scene cube --width 640 --height 480 \
      --frames 16 --warmup 2 --set trace.search=hierarchical --set trace.rays=2 \
      --set trace.deferred=true --set light.layers=two --set light.resolution=512 \
      --set trace.hierarchy=nbuffer --side "x:trace.rays=2" --requested composite.color \
      --out "$TMP/$v-$round.md" >/dev/null
  done
done
python3 bench/stub_table.py --dir "$TMP" --out "$OUT/trace-stubs.md" --column "trace ms" \
  --baseline base --title "trace stub" $TRACE
python3 bench/stub_table.py --dir "$TMP" --out "$OUT/nbuffer-stubs.md" --column "nbuffer ms" \
  --baseline base --title "N-buffer stub" base $NBUFFER
