#include "cli/ProgressBar.h"

#include <unistd.h>

#include <iostream>

namespace ivshadow {

ProgressBar::ProgressBar() : terminal_(isatty(2) != 0) {}

void ProgressBar::update(int done, int total, const std::string& label) {
  constexpr int kWidth = 30;
  const int filled = total > 0 ? done * kWidth / total : kWidth;
  if (terminal_) {
    std::cerr << "\r[" << std::string(std::size_t(filled), '#')
              << std::string(std::size_t(kWidth - filled), '.') << "] " << done << "/" << total
              << " " << label << "\033[K" << std::flush;
    if (done == total) std::cerr << '\n';
  } else {
    std::cerr << "[" << done << "/" << total << "] " << label << '\n';
  }
}

}  // namespace ivshadow
