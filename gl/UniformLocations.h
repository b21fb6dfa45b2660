#pragma once

#include "ivshadow/Export.h"

#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace ivshadow {

// The locations of a linked program's active uniforms, read once after it is linked, so that
// setting a uniform by name costs a search in memory instead of glGetUniformLocation. An
// array is found by its bare name ("uMapDepth" for "uMapDepth[0]").
class IVSHADOW_INTERNAL UniformLocations {
 public:
  UniformLocations() = default;
  // Reads the active uniforms of `program` in the current context.
  explicit UniformLocations(unsigned int program);

  unsigned int program() const { return program_; }
  // -1, which glProgramUniform* ignores, for a name the program does not use.
  int operator[](std::string_view name) const;

 private:
  unsigned int program_ = 0;
  std::vector<std::pair<std::string, int>> byName_;  // sorted by name
};

}  // namespace ivshadow
