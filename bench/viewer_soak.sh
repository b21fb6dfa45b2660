#!/usr/bin/env bash
# Viewer soak: the bundled SoQt viewer (`ivshadow view`) on its own Xvfb server for SECONDS
# (600 by default) with coloured_shadows.iv, its deep shadow light (method METHOD, MAP by
# default, at 256 texels) dragged in circles by xdotool through the viewer's light dragger the whole time, so
# that every frame drawn rebuilds the map or traces again. The viewer's resident set size is
# sampled every 10 seconds. Prints one Markdown row (first and last RSS, slope over the
# second half) and, with --write, puts it into docs/RELIABILITY.md between its "viewer soak
# table" markers (a row per method).
#   bench/viewer_soak.sh [SECONDS] [METHOD] [--write]
# Needs Xvfb, xdotool, xwininfo and xwd; IVSHADOW_EXE names another ivshadow executable;
# VIEWER_SOAK_KEEP=DIR keeps the pictures of the view before and during the first drag and
# the samples (seconds, RSS in KiB).
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:-600}
method=${2:-MAP}
write=${3:-}
exe=${IVSHADOW_EXE:-build/bin/ivshadow}
work=$(mktemp -d)
display=
for n in $(seq 70 99); do
  if [ ! -e "/tmp/.X11-unix/X$n" ] && [ ! -e "/tmp/.X$n-lock" ]; then
    display=:$n
    break
  fi
done
[ -n "$display" ] || { echo "viewer_soak.sh: no free X display" >&2; exit 1; }
xvfb= viewer=
cleanup() {
  [ -n "$viewer" ] && kill "$viewer" 2>/dev/null || true
  [ -n "$xvfb" ] && kill "$xvfb" 2>/dev/null || true
  wait 2>/dev/null || true
  rm -rf "$work"
}
trap cleanup EXIT
Xvfb "$display" -screen 0 1280x1024x24 -nolisten tcp >"$work/xvfb.log" 2>&1 &
xvfb=$!
export DISPLAY=$display
for _ in $(seq 50); do xdpyinfo >/dev/null 2>&1 && break; sleep 0.2; done

# The light where ViewerDraggerTest puts it, seen by the scene's camera (ViewerDraggerTest
# derives where it projects).
XDG_CONFIG_HOME=$work "$exe" view iv_scenes/coloured_shadows.iv --size 640x480 \
  --set Lamp.method="$method" --set Lamp.resolution=256 --set "Lamp.location=0.4 -0.6 2.5" \
  >"$work/viewer.log" 2>&1 &
viewer=$!
# The 3D area: the largest window without children (the examiner's decorations, the panel
# and the bars are the others), its id, size and place on the screen.
area=
for _ in $(seq 150); do
  area=$(xwininfo -root -tree 2>/dev/null | python3 -c '
import re, sys
lines = sys.stdin.read().split("\n")
best = None
for i, line in enumerate(lines):
    m = re.match(r"\s*(0x[0-9a-f]+) .* (\d+)x(\d+)[+-]-?\d+[+-]-?\d+ +\+(-?\d+)\+(-?\d+)\s*$", line)
    if not m or (i + 1 < len(lines) and "child" in lines[i + 1]):
        continue
    w, h = int(m.group(2)), int(m.group(3))
    if best is None or w * h > best[1] * best[2]:
        best = (m.group(1), w, h, int(m.group(4)), int(m.group(5)))
if best and best[1] >= 200:
    print(*best)' || true)
  [ -n "$area" ] && break
  kill -0 "$viewer" 2>/dev/null || { cat "$work/viewer.log" >&2; exit 1; }
  sleep 0.2
done
[ -n "$area" ] || { echo "viewer_soak.sh: no 3D view appeared" >&2; exit 1; }
read -r window aw ah ax ay <<<"$area"
# The light's pixel: the camera at (0, -7.5, 5.2) turned 0.93 rad about x, heightAngle 0.7;
# the light 7.145 units along the view, 1.961 above its axis and 0.4 right of it.
read -r bx by < <(awk -v w="$aw" -v h="$ah" -v x0="$ax" -v y0="$ay" 'BEGIN {
  t = sin(0.35) / cos(0.35); a = w / h
  printf "%d %d\n", x0 + (1 + 0.4 / 7.145 / (t * a)) * w / 2, y0 + (1 - 1.961 / 7.145 / t) * h / 2 }')
sleep 5  # the first frames: programs linked, the first map built
# The examiner starts in viewing mode, where a drag turns the camera: Escape (to the window
# under the pointer: there is no window manager) switches it to interaction, where a drag
# moves the dragger.
xdotool mousemove "$((ax + aw / 2))" "$((ay + ah / 2))"
xdotool key Escape
sleep 1
xwd -silent -id "$window" >"$work/before.xwd"

rss() { awk '/^VmRSS:/ {print $2}' "/proc/$viewer/status"; }
samples=()
start=$(date +%s)
next=$start
drags=0
first_drag_checked=
while :; do
  now=$(date +%s)
  [ $((now - start)) -ge "$seconds" ] && break
  kill -0 "$viewer" 2>/dev/null || { echo "viewer_soak.sh: the viewer exited" >&2; cat "$work/viewer.log" >&2; exit 1; }
  if [ "$now" -ge "$next" ]; then
    samples+=("$((now - start)) $(rss)")
    next=$((next + 10))
  fi
  # One drag: press on the ball, a circle of 40 pixels around it in 24 steps, release where
  # it started.
  xdotool mousemove "$bx" "$by" mousedown 1
  for step in $(seq 0 24); do
    read -r dx dy < <(awk -v s="$step" 'BEGIN { a = s * 6.2832 / 24; printf "%d %d\n", 40 * sin(a), 40 * (1 - cos(a)) * 0.5 }')
    xdotool mousemove "$((bx + dx))" "$((by + dy))"
    sleep 0.05
  done
  xdotool mousemove "$bx" "$by" mouseup 1
  drags=$((drags + 1))
  if [ -z "$first_drag_checked" ]; then
    # Mid-drag picture against the one before: the shadows moved (a drag that turned the
    # camera instead would change nearly every pixel).
    xdotool mousemove "$bx" "$by" mousedown 1 mousemove "$((bx + 30))" "$by"
    sleep 1
    xwd -silent -id "$window" >"$work/during.xwd"
    xdotool mousemove "$bx" "$by" mouseup 1
    changed=$(cmp -l "$work/before.xwd" "$work/during.xwd" 2>/dev/null | wc -l || true)
    total=$(stat -c %s "$work/before.xwd")
    echo "first drag: $changed of $total bytes of the view changed" >&2
    [ -n "${VIEWER_SOAK_KEEP:-}" ] && cp "$work"/*.xwd "$VIEWER_SOAK_KEEP"/
    first_drag_checked=1
  fi
done
samples+=("$(($(date +%s) - start)) $(rss)")
[ -n "${VIEWER_SOAK_KEEP:-}" ] && printf '%s\n' "${samples[@]}" >"$VIEWER_SOAK_KEEP/samples-$method.txt"
row=$(printf '%s\n' "${samples[@]}" | python3 -c '
import sys
pts = [tuple(map(float, l.split())) for l in sys.stdin if l.strip()]
half = pts[len(pts) // 2:]
n = len(half); sx = sum(p[0] for p in half); sy = sum(p[1] for p in half)
sxx = sum(p[0] ** 2 for p in half); sxy = sum(p[0] * p[1] for p in half)
d = n * sxx - sx * sx
slope = 60.0 * (n * sxy - sx * sy) / d if d > 0 else 0.0
print("| viewer, %s, light dragged | %d s, %s drags | %.1f | %.1f | %.1f | %.0f |" % (
    sys.argv[1], pts[-1][0], sys.argv[2], pts[0][1] / 1024, pts[-1][1] / 1024,
    max(p[1] for p in pts) / 1024, slope))' "$method" "$drags")
echo "$row"
if [ "$write" = --write ]; then
  python3 - "$row" "$method" <<'PY'
import re, sys
path = "docs/RELIABILITY.md"
text = open(path).read()
row, method = sys.argv[1], sys.argv[2]
def replace(m):
    rows = [r for r in m.group(2).split("\n") if r and not r.startswith("| viewer, %s," % method)]
    return m.group(1) + "\n".join(rows + [row]) + m.group(3)
text = re.sub(r"(<!-- viewer soak table -->\n(?:\|[^\n]*\n){2})(.*?)(\n<!-- /viewer soak table -->)",
              replace, text, flags=re.S)
open(path, "w").write(text)
PY
fi
