#include "image_files/CommandPaths.h"

#include "image_files/AtomicFile.h"
#include "scene/InputError.h"

#include <filesystem>

namespace ivshadow {

CommandPaths& CommandPaths::input(const std::string& option, const std::string& path) {
  if (!path.empty()) inputs_.push_back({option, path});
  return *this;
}

CommandPaths& CommandPaths::output(const std::string& option, const std::string& path) {
  if (!path.empty()) outputs_.push_back({option, path});
  return *this;
}

bool CommandPaths::sameFile(const std::string& a, const std::string& b) {
  namespace fs = std::filesystem;
  std::error_code ec;
  // The files the writes would reach: a dangling link names the file it would create.
  const fs::path first = AtomicFile::finalTarget(a), second = AtomicFile::finalTarget(b);
  if (fs::exists(first, ec) && fs::exists(second, ec)) {
    const bool same = fs::equivalent(first, second, ec);
    return same && !ec;
  }
  const fs::path x = fs::weakly_canonical(first, ec);
  if (ec) return first.lexically_normal() == second.lexically_normal();
  const fs::path y = fs::weakly_canonical(second, ec);
  return !ec && x == y;
}

void CommandPaths::check() const {
  for (std::size_t i = 0; i < outputs_.size(); ++i) {
    const Named& output = outputs_[i];
    for (const Named& input : inputs_)
      if (sameFile(output.path, input.path))
        throw InputError(output.path + ": error: " + output.option + " names the input " +
                         input.option + " (" + input.path + "); an output never replaces an input");
    if (AtomicFile::writesInPlace(output.path)) continue;
    for (std::size_t j = 0; j < i; ++j)
      if (sameFile(output.path, outputs_[j].path))
        throw InputError(output.path + ": error: " + outputs_[j].option + " and " + output.option +
                         " name the same file (" + outputs_[j].path +
                         "); each output needs a file of its own");
  }
}

}  // namespace ivshadow
