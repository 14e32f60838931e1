#!/usr/bin/env bash
# Drives penumbra's window with real X input events (xdotool), as a user would: in a single
# view of the cube at 1280x800, the view's output drop-down is opened and entries lying over
# the image are clicked, several times; Esc is pressed; Ctrl+Q closes the window. Run under
# its own X server (test_window_real_input.cpp: xvfb-run -a -s '-screen 0 1280x800x24').
#
#   real_input_combo.sh PENUMBRA WORKDIR OUTPUTS PAIRS
# OUTPUTS: every output in the order of the drop-down ("light.light gbuffer.albedo ...");
# PAIRS: "from>to ..." (pick `from`, then `to`).
# Prints one line per step ("shown OUTPUT at X Y (over the image: yes)", "alive after Esc",
# "exit N"); "FAILED: ..." and status 1 when the window closed or a step could not be done.
set -u
bin=$1
work=$2
read -r -a outputs <<<"$3"
read -r -a pairs <<<"$4"
cd "$work" || exit 1

fail() {
  echo "FAILED: $*"
  [ -n "${pid:-}" ] && kill -0 "$pid" 2>/dev/null && kill "$pid"
  echo "--- penumbra stderr:"; cat app.err 2>/dev/null
  exit 1
}

# 1. Where view A lies (the app's own layout report), then the window itself.
echo '[{"print_layout": "calibrate"}]' >calibrate.json
"$bin" --width 1280 --height 800 --script calibrate.json >calibrate.out 2>&1 || fail "calibration run: $(cat calibrate.out)"
read -r vx vy vw vh < <(sed -n 's|.*window ##views/view_A[^ ]* at \([0-9]*\) \([0-9]*\) size \([0-9]*\) \([0-9]*\).*|\1 \2 \3 \4|p' calibrate.out)
[ -n "${vx:-}" ] || fail "no view A in the layout report: $(cat calibrate.out)"

"$bin" --width 1280 --height 800 >app.out 2>app.err &
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
click() { xdotool mousemove $((wx + $1)) $((wy + $2)) click 1; }
wheel() { xdotool mousemove $((wx + $1)) $((wy + $2)) click --repeat "$3" --delay 5 "$4"; }

# 2. Barriers. ImGui 1.86 reads held keys, not presses (a tap shorter than a frame is lost),
#    so a key is held until what it does has happened: F12 until a new screenshot is written.
#    Every event sent before has then been handled by the frame that wrote it, and every
#    event sent after reaches a later frame. save: Ctrl+S held until the settings file is
#    written (the view's state), then a barrier, so Ctrl is seen released before any wheel
#    (ImGui does not scroll while Ctrl is down). A press sent before the window had the
#    keyboard is lost: pressed again after 3 s.
holdUntil() {  # KEYS TEST
  for _ in $(seq 1 10); do
    xdotool keydown "$1"
    for _ in $(seq 1 60); do
      eval "$2" && break
      alive
      sleep 0.05
    done
    xdotool keyup "$1"
    eval "$2" && return 0
  done
  return 1
}
shots() { ls penumbra_screenshot_*.png 2>/dev/null | wc -l; }
barrier() {
  local before
  before=$(shots)
  holdUntil F12 '[ "$(shots)" -gt "$before" ]' || fail "F12 wrote no screenshot"
}
saves=0
save() {
  rm -f penumbra_settings.json
  holdUntil ctrl+s '[ -s penumbra_settings.json ]' || fail "Ctrl+S wrote no settings"
  saves=$((saves + 1))
  barrier
}
shownOutput() { sed -n 's/.*"output": *"\([^"]*\)".*/\1/p' penumbra_settings.json | head -1; }

# 3. The geometry of ImGui 1.86's default style at UI scale 1: the combo is the view's first
#    item (window padding 8), one frame (19 px) high; its list opens below it, 8 entries of
#    17 px visible (13 px font + 4 px spacing, padding 8), scrolled 65 px per wheel notch
#    (5 lines). The image starts below the toolbar's two lines.
comboX=$((vx + 8 + 100)) comboY=$((vy + 8 + 9))
listTop=$((vy + 8 + 19)) listHeight=148 pitch=17 notch=65
imageTop=$((vy + 8 + 3 * 23))
count=${#outputs[@]}
maxScroll=$((pitch * count - 4 - (listHeight - 16)))
index() { for i in "${!outputs[@]}"; do [ "${outputs[$i]}" = "$1" ] && echo "$i" && return; done; echo -1; }

pick() {
  local name=$1 i
  i=$(index "$name")
  [ "$i" -ge 0 ] || fail "no output $name"
  click "$comboX" "$comboY"
  # A popup is hidden in its first frame (ImGui sizes it then): a wheel in that frame goes to
  # the view underneath, and ImGui keeps sending wheels there for 2 s. Two frames pass first.
  barrier
  barrier
  # Scroll to the top, then down by whole notches until the entry is in view: a notch (65
  # px) is less than the lower part of the list (over the image, 76 px), so it lands there
  # unless the list ends first.
  wheel "$comboX" $((listTop + 60)) 40 4
  barrier
  local notches=0 scroll=0 y
  y=$((listTop + 14 + pitch * i))
  while [ "$y" -gt $((listTop + 136)) ] && [ "$scroll" -lt "$maxScroll" ]; do
    notches=$((notches + 1))
    scroll=$((notch * notches)); [ "$scroll" -gt "$maxScroll" ] && scroll=$maxScroll
    y=$((listTop + 14 + pitch * i - scroll))
  done
  [ "$y" -le $((listTop + 136)) ] || fail "$name lies outside the list (y $y)"
  if [ "$notches" -gt 0 ]; then
    wheel "$comboX" $((listTop + 60)) "$notches" 5
    barrier
  fi
  click $((comboX - 60)) "$y"
  local shown=""
  for _ in 1 2 3; do  # the click may share the saving frame: then the next save shows it
    save
    shown=$(shownOutput)
    [ "$shown" = "$name" ] && break
  done
  alive
  local over=no
  [ "$y" -gt "$imageTop" ] && over=yes
  if [ "$shown" != "$name" ]; then  # the entry under the click was another one
    import -window root "wrong_$name.png" 2>/dev/null
    echo "clicked at y $y for $name, the view shows $shown"
    return 1
  fi
  echo "shown $shown at $((comboX - 60)) $y (over the image: $over) after ${SECONDS}s, $saves saves"
}
# A wheel that ImGui sent to another window (it keeps sending wheels to the last window
# scrolled for 2 s) leaves the list where it was, and the click picks another entry: the
# window must show that one, and the pick is tried again once the 2 s are over.
pickRetrying() {
  for attempt in 1 2 3; do
    pick "$1" && return 0
    sleep 2.2
  done
  fail "could not pick $1"
}

barrier  # the first frames are drawn
echo "first frames after ${SECONDS}s"
for pair in "${pairs[@]}"; do
  pickRetrying "${pair%%>*}"
  pickRetrying "${pair##*>}"
done
import -window root last_pick.png 2>/dev/null

# 4. Esc does not close the window; Ctrl+Q does, cleanly.
xdotool keydown Escape
barrier
xdotool keyup Escape
barrier
alive
echo "alive after Esc (${SECONDS}s)"
xdotool keydown ctrl+q
for _ in $(seq 1 400); do kill -0 "$pid" 2>/dev/null || break; sleep 0.05; done
xdotool keyup ctrl+q
kill -0 "$pid" 2>/dev/null && fail "Ctrl+Q did not close the window"
wait "$pid"
echo "exit $?"
echo "--- penumbra stderr:"
cat app.err
