"""The `ivshadow variants-worker` that render() keeps for a loop of renders (docs/CLI.md,
"How `variants` renders"): one process and GL context for all the renders of this Python
process, so that each render after the first pays for its scene and picture only.

The worker renders each request as `ivshadow render` would, to the bit, and answers with the
exit status that command would have had; what the render says on stderr goes to a log file
named in the request. A worker that dies while it renders is started again and the render
retried once, as `ivshadow variants` does; a render that dies there too raises, as a crashed
render process did.
"""

import json
import os
import subprocess
import threading


class RenderWorker:
    """One worker process, started on first use and again after it ended: after a failed
    render (other than bad input) the worker ends on its own, so that no render inherits what
    a failed one left behind."""

    def __init__(self):
        self._process = None
        # The process's working directory and executable when the worker started: requests
        # name paths as the caller gave them, relative to the caller's directory.
        self._started_in = None
        self._lock = threading.Lock()

    def try_render(self, executable, request):
        """The exit status of the render `request` asks for (a dict of workerRequest's keys,
        cli/VariantsWorker.h): the render's, or the worker's own (-signal) when it died in
        the retry too. None when another thread is using the worker: the caller then renders
        in a process of its own, so that threads still render side by side."""
        if not self._lock.acquire(blocking=False):
            return None
        try:
            place = (os.getpid(), os.getcwd(), executable)
            if self._process is not None and self._started_in != place:
                # Another directory or executable, or a child of a fork, whose parent's pipes
                # these are: a worker of its own.
                self._end(wait=self._started_in[0] == os.getpid())
            line = json.dumps(request) + "\n"
            for _ in range(2):
                if self._process is None:
                    self._start(executable, place)
                try:
                    answer = self._ask(line)
                except BaseException:
                    # Interrupted between the request and its answer (Ctrl-C, a line that is
                    # not JSON): the answer left unread would be taken for the next render's.
                    self._process.kill()
                    self._end(wait=True)
                    raise
                if answer is not None:
                    if answer.get("last"):
                        self._end(wait=True)
                    return answer["exit"]
                # The worker died with the render: what killed it may have been left by an
                # earlier render, so the render gets a fresh worker once.
                died = self._end(wait=True)
            return died if died != 0 else 1
        finally:
            self._lock.release()

    def close(self):
        with self._lock:
            if self._process is not None and self._started_in[0] == os.getpid():
                self._end(wait=True)

    def _start(self, executable, place):
        self._process = subprocess.Popen([executable, "variants-worker"], stdin=subprocess.PIPE,
                                         stdout=subprocess.PIPE, stderr=subprocess.DEVNULL,
                                         text=True)
        self._started_in = place

    def _ask(self, line):
        """The worker's answer to `line` as a dict, or None when it died first."""
        try:
            self._process.stdin.write(line)
            self._process.stdin.flush()
            answer = self._process.stdout.readline()
        except OSError:  # a broken pipe: it died before reading
            return None
        return json.loads(answer) if answer else None

    def _end(self, wait):
        """Ends the worker (closing its stdin ends it) and returns its exit status, -signal
        when a signal ended it; without `wait` (a fork's child) only lets go of it."""
        process, self._process = self._process, None
        if process is None or not wait:
            return None
        try:
            process.stdin.close()
        except OSError:
            pass
        status = process.wait()
        process.stdout.close()
        return status
