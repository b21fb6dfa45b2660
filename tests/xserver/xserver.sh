#!/usr/bin/env bash
# One X server (Xvfb) with a window manager (openbox) for the whole viewer suite, started and
# stopped as a CTest fixture (tests/CMakeLists.txt), instead of an `xvfb-run -a` per test:
# xvfb-run's own clean-up failed at random on a loaded machine and its exit status 5 replaced
# the viewer's.
#   xserver.sh start DIR   starts Xvfb on a free display and openbox on each of its screens,
#                          writes DIR/display (":N") and the pids
#   xserver.sh stop DIR    stops what `start` started: the window managers, then the server
# The server has four screens: :N.0 (IVSHADOW_TEST_SCREEN, 1280x1024 by default) for the
# scripted viewer tests, and :N.1 1280x1024, :N.2 1024x768 and :N.3 1920x1080 for the tests
# that look at the interactive window as users see it (ViewerWindowTest.cpp) or read windows
# back from the screen (the FreeCAD and headlight tests), one at a time (RESOURCE_LOCK
# interactive_screens), where no other test's window may come on top; screens of several sizes without a server each. Openbox
# manages one screen per process, hence one per screen; with it, windows get a frame and a
# place as on a desktop.
# The server and its clients run detached from CTest's pipes, so CTest does not wait on them.
set -euo pipefail
action=${1:?usage: xserver.sh start|stop DIR}
dir=${2:?usage: xserver.sh start|stop DIR}
screens=("${IVSHADOW_TEST_SCREEN:-1280x1024x24}" 1280x1024x24 1024x768x24 1920x1080x24)

# Ends the processes whose pid files are named, all at once (each takes a second or two).
stop_pids() {
  local pids=() pidfile pid
  for pidfile in "$@"; do
    [ -f "$pidfile" ] || continue
    pids+=("$(cat "$pidfile")")
    rm -f "$pidfile"
  done
  [ ${#pids[@]} -eq 0 ] && return 0
  kill "${pids[@]}" 2>/dev/null || true
  for pid in "${pids[@]}"; do
    for _ in $(seq 50); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
    kill -9 "$pid" 2>/dev/null || true
  done
}

stop() {
  # The window managers first: a server that goes first leaves them failing on a lost display.
  stop_pids "$dir"/openbox.*.pid
  stop_pids "$dir/xvfb.pid"
  rm -f "$dir/display"
}

# Starts openbox on screen $1 of display $2 and waits until it manages the screen (it then
# names itself on the root window, _NET_SUPPORTING_WM_CHECK).
start_window_manager() {
  local screen=$1 display=$2
  # Its own configuration and cache, not the user's.
  HOME="$dir/home" DISPLAY="$display.$screen" setsid openbox --sm-disable \
    >"$dir/openbox.$screen.log" 2>&1 </dev/null &
  echo $! >"$dir/openbox.$screen.pid"
  for _ in $(seq 200); do
    xprop -display "$display.$screen" -root _NET_SUPPORTING_WM_CHECK 2>/dev/null |
      grep -q "window id" && return 0
    kill -0 "$(cat "$dir/openbox.$screen.pid")" 2>/dev/null || break
    sleep 0.05
  done
  cat "$dir/openbox.$screen.log" >&2
  echo "openbox did not start on $display.$screen" >&2
  exit 1
}

case "$action" in
  start)
    mkdir -p "$dir"
    stop
    # -displayfd: the server picks a free display itself and writes its number when it is
    # ready to accept clients, so there is no race between choosing and binding a display.
    # Removed first: the redirection below empties it only once the child runs, so a number
    # left from the last run could be read before that.
    rm -f "$dir/display.number"
    screen_options=()
    for i in "${!screens[@]}"; do screen_options+=(-screen "$i" "${screens[$i]}"); done
    setsid Xvfb -displayfd 3 "${screen_options[@]}" -nolisten tcp -noreset \
      3>"$dir/display.number" >"$dir/xvfb.log" 2>&1 </dev/null &
    echo $! >"$dir/xvfb.pid"
    for _ in $(seq 200); do
      [ -s "$dir/display.number" ] && break
      kill -0 "$(cat "$dir/xvfb.pid")" 2>/dev/null || { cat "$dir/xvfb.log" >&2; exit 1; }
      sleep 0.05
    done
    [ -s "$dir/display.number" ] || { echo "Xvfb did not start in 10 s" >&2; exit 1; }
    display=":$(tr -d '\n' <"$dir/display.number")"
    mkdir -p "$dir/home"
    for i in "${!screens[@]}"; do start_window_manager "$i" "$display"; done
    echo "$display" >"$dir/display"
    echo "X server on $display (screens ${screens[*]}), openbox on each"
    ;;
  stop)
    stop
    ;;
  *)
    echo "usage: xserver.sh start|stop DIR" >&2
    exit 2
    ;;
esac
