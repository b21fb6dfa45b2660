#include "cli/OutputDirectory.h"

#include "scene/InputError.h"

#include <filesystem>
#include <system_error>

namespace ivshadow {

void OutputDirectory::check() const {
  namespace fs = std::filesystem;
  if (path.empty())
    throw InputError(option + " '': error: expected a directory for " + contents +
                     ", got an empty name");
  // The deepest part of the path that exists must be a directory: create_directories
  // otherwise fails with a bare "Not a directory" that names neither the option nor the part.
  std::error_code ec;
  for (fs::path part = fs::path(path); !part.empty(); part = part.parent_path()) {
    const fs::file_status status = fs::status(part, ec);
    if (!fs::exists(status)) {
      if (part == part.parent_path()) break;
      continue;
    }
    if (fs::is_directory(status)) return;
    const std::string what = part == fs::path(path) ? path : part.string() + " (in " + path + ")";
    throw InputError(path + ": error: " + option + " expects a directory for " + contents +
                     ", but " + what +
                     (fs::is_regular_file(status) ? " is a file" : " is not a directory"));
  }
}

void OutputDirectory::create() const {
  check();
  std::error_code ec;
  std::filesystem::create_directories(path, ec);
  if (ec || !std::filesystem::is_directory(path))
    throw InputError(path + ": error: cannot create the directory " + option + " names for " +
                     contents + (ec ? ": " + ec.message() : std::string()));
}

}  // namespace ivshadow
