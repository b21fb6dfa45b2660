#!/usr/bin/env bash
# One X server (Xvfb) for the whole viewer suite, started and stopped as a CTest fixture
# (tests/CMakeLists.txt), instead of an `xvfb-run -a` per test: xvfb-run's own clean-up failed
# at random on a loaded machine and its exit status 5 replaced the viewer's.
#   xserver.sh start DIR   starts Xvfb on a free display, writes DIR/display (":N") and the pids
#   xserver.sh stop DIR    stops what `start` started
# The server and its clients run detached from CTest's pipes, so CTest does not wait on them.
set -euo pipefail
action=${1:?usage: xserver.sh start|stop DIR}
dir=${2:?usage: xserver.sh start|stop DIR}
screen=${IVSHADOW_TEST_SCREEN:-1280x1024x24}

stop() {
  for pidfile in "$dir"/*.pid; do
    [ -f "$pidfile" ] || continue
    pid=$(cat "$pidfile")
    kill "$pid" 2>/dev/null || true
    for _ in $(seq 50); do kill -0 "$pid" 2>/dev/null || break; sleep 0.1; done
    kill -9 "$pid" 2>/dev/null || true
    rm -f "$pidfile"
  done
  rm -f "$dir/display"
}

case "$action" in
  start)
    mkdir -p "$dir"
    stop
    # -displayfd: the server picks a free display itself and writes its number when it is
    # ready to accept clients, so there is no race between choosing and binding a display.
    setsid Xvfb -displayfd 3 -screen 0 "$screen" -nolisten tcp -noreset \
      3>"$dir/display.number" >"$dir/xvfb.log" 2>&1 </dev/null &
    echo $! >"$dir/xvfb.pid"
    for _ in $(seq 200); do
      [ -s "$dir/display.number" ] && break
      kill -0 "$(cat "$dir/xvfb.pid")" 2>/dev/null || { cat "$dir/xvfb.log" >&2; exit 1; }
      sleep 0.05
    done
    [ -s "$dir/display.number" ] || { echo "Xvfb did not start in 10 s" >&2; exit 1; }
    echo ":$(tr -d '\n' <"$dir/display.number")" >"$dir/display"
    echo "X server on $(cat "$dir/display") ($screen)"
    ;;
  stop)
    stop
    ;;
  *)
    echo "usage: xserver.sh start|stop DIR" >&2
    exit 2
    ;;
esac
