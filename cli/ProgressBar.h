#pragma once

#include <string>

namespace ivshadow {

// A progress line on standard error: a bar redrawn in place on a terminal, one line per
// step otherwise (logs, CI).
class ProgressBar {
 public:
  ProgressBar();
  void update(int done, int total, const std::string& label);
  bool terminal() const { return terminal_; }

 private:
  bool terminal_;
};

}  // namespace ivshadow
