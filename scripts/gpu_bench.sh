#!/bin/bash
# The first GPU numbers: on a machine with an NVIDIA GPU and no display, builds penumbra,
# checks that the headless EGL context is not llvmpipe, and runs bench-stages and the
# `default` and `thesis-table-4.1` bench presets; off llvmpipe the pipeline times every
# stage with GL_TIME_ELAPSED timer queries (Pipeline::timingMethod). One results folder:
# renderer.txt, calibration/ (the renderer's `auto` calibration, docs/decisions/071),
# stages.md, default/, thesis-table-4.1/, log.txt. Meant to finish in under 8 minutes (a lent
# machine gives a whole session 15 minutes of device time). No GPU number exists until this
# has run on a GPU: every number in docs/ so far is llvmpipe's.
#   bash scripts/gpu_bench.sh [OUT]            on the GPU machine (the device tool's README
#                                              says how to bring the EGL/GL libraries there)
#   DRY_RUN=1 BIN=build/penumbra bash scripts/gpu_bench.sh   anywhere: no build, the renderer
#                                              is reported but not required, every command
#                                              runs at a tiny size to check the plumbing
set -euo pipefail
OUT=${1:-gpu-results}
DRY_RUN=${DRY_RUN:-0}
mkdir -p "$OUT"
exec > >(tee "$OUT/log.txt") 2>&1
start=$(date +%s)
if [ -z "${BIN:-}" ]; then
  cmake -S . -B build-gpu -DCMAKE_BUILD_TYPE=Release >/dev/null
  cmake --build build-gpu -j"$(nproc)" --target penumbra | tail -2
  BIN=build-gpu/penumbra
fi
# 1. The renderer, from a tiny export's run.json.
PENUMBRA_CALIBRATION=fallback "$BIN" export --scene cube --width 32 --height 32 --out "$OUT/probe" >/dev/null
python3 -c "import json,sys; r=json.load(open(sys.argv[1])); print(r.get('renderer') or r.get('gl', {}).get('renderer') or r)" \
  "$OUT/probe/run.json" | head -c 400 > "$OUT/renderer.txt"
echo "renderer: $(cat "$OUT/renderer.txt")"
rm -rf "$OUT/probe"
if grep -qi -e llvmpipe -e softpipe "$OUT/renderer.txt"; then
  if [ "$DRY_RUN" = 1 ]; then echo "dry run: a software renderer; the numbers below are not GPU numbers"
  else echo "gpu_bench: the context is a software renderer, not the GPU: no numbers taken" >&2; exit 1; fi
fi
# 2. The renderer's calibration (`auto`'s crossovers), measured and kept with the results; the
#    runs below use it (the bench presets' `auto` parameters choose with it).
export XDG_CACHE_HOME="$OUT/calibration" PENUMBRA_CALIBRATION=cached
"$BIN" calibrate --refresh
# 3. The runs (tiny in a dry run).
if [ "$DRY_RUN" = 1 ]; then
  stages=(--scenes cube --width 64 --height 48 --frames 1)
  bench=(--width 64 --height 48 --frames 1)
else
  stages=(--scenes cube,engine,dragon --frames 15)
  bench=()
fi
"$BIN" bench-stages "${stages[@]}" --out "$OUT/stages.md"
for preset in default thesis-table-4.1; do
  "$BIN" bench --scene cube --preset "$preset" "${bench[@]}" --out "$OUT/$preset"
done
echo "gpu_bench: done in $(( $(date +%s) - start )) s; results in $OUT"
