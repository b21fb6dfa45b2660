#pragma once

#include <string>
#include <vector>

namespace ivshadow {

// The files one command reads and writes, each with the option (or argument) that names it.
// check() is the one place every command asks whether its outputs are safe to write: an
// output that names an input would destroy it, and two outputs naming one file would leave
// only the last, both with exit 0. Files are compared as the file system sees them: through
// symbolic links and other spellings (`./x`, `a/../x`), by identity where the file exists.
class CommandPaths {
 public:
  CommandPaths& input(const std::string& option, const std::string& path);
  // An empty `path` (an option not given) is skipped.
  CommandPaths& output(const std::string& option, const std::string& path);

  // Throws InputError naming both options and the path when an output names an input or
  // another output. Outputs written in place (a device or pipe: `-o /dev/null --stats
  // /dev/null`) may share it, since nothing is replaced there.
  void check() const;

  // Whether `a` and `b` name one file, as check() compares them.
  static bool sameFile(const std::string& a, const std::string& b);

 private:
  struct Named {
    std::string option;
    std::string path;
  };
  std::vector<Named> inputs_;
  std::vector<Named> outputs_;
};

}  // namespace ivshadow
