#!/usr/bin/env bash
# Regenerates the committed result sets under bench/ (bench/README.md): one `penumbra bench`
# run per preset and scene, and `penumbra bench-stages`. Each set is written to a scratch
# directory and moved into place only when its run succeeded, so a failed or stopped run
# leaves the committed set as it was.
#
# Usage: scripts/bench_all.sh [PENUMBRA] [SET ...]
#   PENUMBRA   the program (default build/penumbra)
#   SET        names from the list below (default: all of them)
#   BENCH_ROOT where the sets go (default: bench/ of this checkout)
#
# A full run takes about an hour on two llvmpipe cores; give it a quiet machine, since
# every results.md records the load average before and after its run.
set -euo pipefail
cd "$(dirname "$0")/.."
penumbra="$(realpath "${1:-build/penumbra}")"
shift || true
root="${BENCH_ROOT:-bench}"
[ -x "$penumbra" ] || { echo "bench_all: no program at $penumbra (make program)" >&2; exit 2; }

# name | arguments of `penumbra bench` (the command each committed results.md names)
sets=(
  "cube-default|--scene cube"
  "engine-default|--scene engine"
  "cube-thesis-table-4.1|--scene cube --preset thesis-table-4.1 --width 400 --height 300"
  "engine-thesis-table-4.1|--scene engine --preset thesis-table-4.1"
  "dragon-thesis-table-4.1|--scene dragon --preset thesis-table-4.1 --width 400 --frames 2 --warmup 1 --rounds 1 --reference-samples 8"
  "plate-atty-4.2|--scene plate --preset atty-4.2 --frames 3 --warmup 1 --rounds 1"
  "bunny-atty-4.2|--scene assets/scenes/bunny_atty.json --preset atty-4.2 --set light.fov_degrees=50 --width 192 --height 192 --frames 1 --warmup 0 --rounds 1"
  "dragon-atty-4.2|--scene assets/scenes/dragon_atty.json --preset atty-4.2 --set light.fov_degrees=50 --width 192 --height 192 --frames 1 --warmup 0 --rounds 1"
  "toys-animated|--scene toys --preset animated --width 160 --height 120 --fps 4"
  "dragon_turntable-animated|--scene dragon_turntable --preset animated --width 128 --height 96 --fps 2"
)
known="stages"
for entry in "${sets[@]}"; do known+=" ${entry%%|*}"; done

wanted=("$@")
if [ ${#wanted[@]} -eq 0 ]; then read -r -a wanted <<<"$known"; fi
for name in "${wanted[@]}"; do
  case " $known " in *" $name "*) ;; *) echo "bench_all: unknown set '$name' (one of: $known)" >&2; exit 2 ;; esac
done

mkdir -p "$root"
scratch="$(mktemp -d "${TMPDIR:-/tmp}/penumbra-bench.XXXXXX")"
trap 'rm -rf "$scratch"' EXIT

for name in "${wanted[@]}"; do
  if [ "$name" = stages ]; then
    echo "bench_all: stages -> $root/stages.md"
    "$penumbra" bench-stages --out "$scratch/stages.md"
    mv "$scratch/stages.md" "$root/stages.md"
    continue
  fi
  for entry in "${sets[@]}"; do
    [ "${entry%%|*}" = "$name" ] || continue
    read -r -a args <<<"${entry#*|}"
    echo "bench_all: $name -> $root/$name (penumbra bench ${args[*]})"
    "$penumbra" bench "${args[@]}" --out "$scratch/$name"
    # The results name the command as run; say where the set lives instead of the scratch path.
    sed -i "s|$scratch/$name|$root/$name|g" "$scratch/$name"/results.*
    rm -rf "$root/$name.old"
    [ ! -d "$root/$name" ] || mv "$root/$name" "$root/$name.old"
    mv "$scratch/$name" "$root/$name"
    rm -rf "$root/$name.old"
  done
done
