#pragma once

#include <sys/types.h>

#include <string>
#include <utility>
#include <vector>

namespace ivshadow {

// Where one of a started process's standard streams goes; the streams not named stay this
// process's own.
struct ChildStream {
  int fd = 0;             // the child's stream: 0, 1 or 2
  int from = -1;          // a descriptor of this process duplicated onto it; -1: `path`
  std::string path;       // else the file it writes to
  bool truncate = false;  // `path` created if missing and emptied

  // The child's `fd` is this process's descriptor `from`.
  static ChildStream descriptor(int fd, int from) { return {fd, from, {}, false}; }
  // The child's `fd` writes to the file `path`, which is there (/dev/null).
  static ChildStream writeTo(int fd, std::string path) { return {fd, -1, std::move(path), false}; }
  // The child's `fd` writes to the file `path`, created or emptied: a log of this start alone.
  static ChildStream freshFile(int fd, std::string path) { return {fd, -1, std::move(path), true}; }
};

// Starts `arguments[0]` with `arguments` (no shell, this process's environment) with its
// streams as `streams` say, and returns its process id. Throws std::runtime_error naming the
// executable when it cannot be started. The one place the command line spawns processes, for
// a render process per variant (ChildProcesses) and for long-lived workers (RenderWorkers).
pid_t spawnChild(const std::vector<std::string>& arguments,
                 const std::vector<ChildStream>& streams);

}  // namespace ivshadow
