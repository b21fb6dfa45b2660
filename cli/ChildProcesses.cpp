#include "cli/ChildProcesses.h"

#include "cli/ChildSpawn.h"

#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <stdexcept>

namespace ivshadow {

void ChildProcesses::start(int id, const std::vector<std::string>& arguments,
                           const std::string& stderrPath) {
  const pid_t pid = spawnChild(
      arguments, {ChildStream::writeTo(1, "/dev/null"), ChildStream::freshFile(2, stderrPath)});
  running_.push_back({pid, id});
}

ChildProcesses::Finished ChildProcesses::waitAny() {
  for (;;) {
    int status = 0;
    const pid_t pid = waitpid(-1, &status, 0);
    if (pid < 0) {
      if (errno == EINTR) continue;
      throw std::runtime_error(std::string("waiting for a render process: ") +
                               std::strerror(errno));
    }
    const auto found = std::find_if(running_.begin(), running_.end(),
                                    [pid](const Running& r) { return r.pid == pid; });
    if (found == running_.end()) continue;  // not one of ours
    Finished finished;
    finished.id = found->id;
    finished.exitCode = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    running_.erase(found);
    return finished;
  }
}

void ChildProcesses::signalAll(int signal) const {
  for (const Running& child : running_) kill(child.pid, signal);
}

std::string currentExecutable() {
  char path[4096];
  const ssize_t length = readlink("/proc/self/exe", path, sizeof(path) - 1);
  if (length <= 0) throw std::runtime_error("cannot find the running executable");
  return std::string(path, std::size_t(length));
}

}  // namespace ivshadow
