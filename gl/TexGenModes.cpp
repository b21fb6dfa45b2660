#include "gl/TexGenModes.h"

#include "gl/GlLimits.h"
#include "gl/ShadingLocations.h"

#include <epoxy/gl.h>

namespace ivshadow {

TexGenModes currentTexGenModes() {
  // Texgen state belongs to the active texture unit; Coin leaves unit 0 active between
  // nodes, but a node of someone else's may not.
  const GLint active = glInteger(GL_ACTIVE_TEXTURE);
  if (active != GL_TEXTURE0) glActiveTexture(GL_TEXTURE0);
  const GLenum coordinates[4] = {GL_S, GL_T, GL_R, GL_Q};
  TexGenModes modes{};
  for (int i = 0; i < 4; ++i) {
    GLint mode = 0;
    glGetTexGeniv(coordinates[i], GL_TEXTURE_GEN_MODE, &mode);
    modes[std::size_t(i)] = mode;
  }
  if (active != GL_TEXTURE0) glActiveTexture(GLenum(active));
  return modes;
}

void setTexGenModes(const ShadingLocations& program, const TexGenModes& modes) {
  glProgramUniform4iv(program.program, program.uTexGen, 1, modes.data());
}

}  // namespace ivshadow
