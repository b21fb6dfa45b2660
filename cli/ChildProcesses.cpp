#include "cli/ChildProcesses.h"

#include <fcntl.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <stdexcept>

extern char** environ;

namespace ivshadow {

void ChildProcesses::start(int id, const std::vector<std::string>& arguments,
                           const std::string& stderrPath) {
  std::vector<char*> argv;
  for (const std::string& argument : arguments) argv.push_back(const_cast<char*>(argument.c_str()));
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 2, stderrPath.c_str(), O_WRONLY | O_CREAT | O_TRUNC,
                                   0644);
  pid_t pid = 0;
  const int status = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  if (status != 0)
    throw std::runtime_error("cannot start " + arguments[0] + ": " + std::strerror(status));
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
