#include "gl/UniformLocations.h"

#include <epoxy/gl.h>

#include <algorithm>

namespace ivshadow {

UniformLocations::UniformLocations(unsigned int program) : program_(program) {
  GLint count = 0, longest = 0;
  glGetProgramiv(program, GL_ACTIVE_UNIFORMS, &count);
  glGetProgramiv(program, GL_ACTIVE_UNIFORM_MAX_LENGTH, &longest);
  std::vector<char> name(std::size_t(std::max(longest, 1)), '\0');
  for (GLuint i = 0; i < GLuint(count); ++i) {
    GLsizei length = 0;
    glGetActiveUniformName(program, i, GLsizei(name.size()), &length, name.data());
    std::string text(name.data(), std::size_t(length));
    const GLint location = glGetUniformLocation(program, text.c_str());
    // Built-in (gl_*) uniforms and members of blocks have no location to set.
    if (location < 0) continue;
    const std::size_t bracket = text.find('[');
    if (bracket != std::string::npos) text.resize(bracket);
    byName_.emplace_back(std::move(text), location);
  }
  std::sort(byName_.begin(), byName_.end());
}

int UniformLocations::operator[](std::string_view name) const {
  const auto found =
      std::lower_bound(byName_.begin(), byName_.end(), name,
                       [](const std::pair<std::string, int>& entry, std::string_view key) {
                         return std::string_view(entry.first) < key;
                       });
  return found != byName_.end() && found->first == name ? found->second : -1;
}

}  // namespace ivshadow
