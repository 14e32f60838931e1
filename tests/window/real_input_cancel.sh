#!/usr/bin/env bash
# Drives penumbra's window with real X input events (xdotool): a soft-shadow-map run that
# would take many minutes (a plate 0.02 below its light, ssm.resolution=512, no budget) is
# started; once the window says the run is taking long, its Cancel button (the "running"
# overlay, centred on the window) is clicked with the mouse; the run must stop, the window
# stay open, and Ctrl+Q then close it with status 0. Run under its own X server
# (test_window_real_input.cpp: xvfb-run -a -s '-screen 0 1280x800x24').
#
#   real_input_cancel.sh PENUMBRA WORKDIR
# Prints "overlay shown after Ns", "cancelled after Ns", "alive after cancel", "exit N";
# "FAILED: ..." and status 1 when a step could not be done.
set -u
bin=$1
work=$2
cd "$work" || exit 1

fail() {
  echo "FAILED: $*"
  [ -n "${pid:-}" ] && kill -0 "$pid" 2>/dev/null && kill "$pid"
  echo "--- penumbra stderr:"; cat app.err 2>/dev/null
  exit 1
}

# The plate of tests/stages/test_ssm_cost.cpp: a unit square at y = 1 (4 vertices, 2
# triangles), its unit light at y = 1.02 over a receiver-only ground.
echo 'AAAAvwAAgD8AAAC/AAAAPwAAgD8AAAC/AAAAPwAAgD8AAAA/AAAAvwAAgD8AAAA/AAACAAEAAAADAAIA' | base64 -d >plate.bin
cat >plate.gltf <<'JSON'
{"asset": {"version": "2.0"}, "scene": 0, "scenes": [{"nodes": [0]}], "nodes": [{"mesh": 0}],
 "meshes": [{"primitives": [{"attributes": {"POSITION": 0}, "indices": 1}]}],
 "buffers": [{"uri": "plate.bin", "byteLength": 60}],
 "bufferViews": [{"buffer": 0, "byteOffset": 0, "byteLength": 48},
                 {"buffer": 0, "byteOffset": 48, "byteLength": 12}],
 "accessors": [{"bufferView": 0, "componentType": 5126, "count": 4, "type": "VEC3",
                "min": [-0.5, 1, -0.5], "max": [0.5, 1, 0.5]},
               {"bufferView": 1, "componentType": 5123, "count": 6, "type": "SCALAR"}]}
JSON
cat >plate.json <<'JSON'
{"name": "plate under its light",
 "objects": [{"gltf": "plate.gltf", "name": "plate"},
             {"ground": {"size": 12, "y": 0}, "receiver_only": true}],
 "light": {"center": [0, 1.02, 0], "forward": [0, -1, 0], "up": [0, 0, -1], "width": 1, "height": 1},
 "camera": {"position": [0, 3.5, 4.5], "target": [0, 0.2, 0]}}
JSON

"$bin" --scene plate.json --set composite.shadow=ssm --set ssm.resolution=512 --set ssm.budget=0 \
  --width 1280 --height 800 >app.out 2>app.err &
pid=$!
for _ in $(seq 1 200); do
  wid=$(xdotool search --pid "$pid" 2>/dev/null | head -1)
  [ -n "$wid" ] && break
  kill -0 "$pid" 2>/dev/null || fail "penumbra exited at start"
  sleep 0.1
done
[ -n "${wid:-}" ] || fail "no window"
read -r wx wy < <(xdotool getwindowgeometry "$wid" | sed -n 's/.*Position: \([0-9]*\),\([0-9]*\).*/\1 \2/p')
alive() { kill -0 "$pid" 2>/dev/null || { wait "$pid"; fail "the window closed (exit $?)"; }; }

# 1. The run announces itself (stderr, with the overlay on screen).
for _ in $(seq 1 1200); do
  grep -q "a run is taking long" app.err && break
  alive
  sleep 0.1
done
grep -q "a run is taking long" app.err || fail "no 'taking long' announcement in 120 s"
echo "overlay shown after ${SECONDS}s"
sleep 1
import -window root overlay.png 2>/dev/null

# 2. A real click on the Cancel button in the window's centre. The button acts on the
#    press (the run's next check may be a whole SSM tile away, seconds on a loaded machine):
#    the button is held down until the run says it was cancelled, then released.
xdotool mousemove $((wx + 640)) $((wy + 400))
sleep 0.5
xdotool mousedown 1
for _ in $(seq 1 1800); do
  grep -q "Cancel clicked" app.err && break
  alive
  sleep 0.1
done
xdotool mouseup 1
grep -q "Cancel clicked" app.err || { import -window root not_cancelled.png 2>/dev/null; fail "the click did not cancel the run in 180 s"; }
echo "cancelled after ${SECONDS}s"
sleep 2
alive
echo "alive after cancel"
import -window root after_cancel.png 2>/dev/null

# 3. Ctrl+Q closes the window (held until it does: ImGui reads held keys).
xdotool keydown ctrl+q
for _ in $(seq 1 400); do kill -0 "$pid" 2>/dev/null || break; sleep 0.05; done
xdotool keyup ctrl+q
kill -0 "$pid" 2>/dev/null && fail "Ctrl+Q did not close the window"
wait "$pid"
echo "exit $?"
echo "--- penumbra stderr:"
cat app.err
