#pragma once

#include <string>

namespace ivshadow {

// The directory a command writes its files into (`trade -o DIR`, `variants -o DIR`, `--slurm
// DIR`). `option` names the option that gave it and `contents` what goes there, for messages.
struct OutputDirectory {
  std::string option;
  std::string path;
  std::string contents;

  // Throws InputError naming the path and what was expected when it cannot become a
  // directory: an empty name, an existing file that is not a directory, or a path through
  // one. Creates nothing, so that a command checks before its work and makes the directory
  // only once its input proved good.
  void check() const;
  // check(), then creates the directory and its parents; a failure (permissions, a read-only
  // file system) is an InputError naming the path and the system's reason.
  void create() const;
};

}  // namespace ivshadow
