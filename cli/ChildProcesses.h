#pragma once

#include <string>
#include <vector>

namespace ivshadow {

// Runs commands as child processes (no shell), at most `limit` at a time.
class ChildProcesses {
 public:
  struct Finished {
    int id = 0;         // as given to start()
    int exitCode = -1;  // -1 when the child was killed by a signal
  };

  explicit ChildProcesses(int limit) : limit_(limit < 1 ? 1 : limit) {}
  bool full() const { return int(running_.size()) >= limit_; }
  bool empty() const { return running_.empty(); }
  // Starts `arguments[0]` with `arguments`; its stdout goes nowhere and its stderr to
  // `stderrPath`. Throws std::runtime_error when the process cannot be started.
  void start(int id, const std::vector<std::string>& arguments, const std::string& stderrPath);
  // Waits for any running child to end.
  Finished waitAny();
  // Sends `signal` to every running child.
  void signalAll(int signal) const;

 private:
  struct Running {
    int pid;
    int id;
  };
  int limit_;
  std::vector<Running> running_;
};

// The path of the running executable (/proc/self/exe).
std::string currentExecutable();

}  // namespace ivshadow
