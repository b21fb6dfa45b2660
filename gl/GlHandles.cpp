#include "gl/GlHandles.h"

#include <epoxy/gl.h>

namespace ivshadow {

void GlTextureRelease::operator()(unsigned int name) const {
  glDeleteTextures(1, &name);
}
void GlBufferRelease::operator()(unsigned int name) const {
  glDeleteBuffers(1, &name);
}
void GlVertexArrayRelease::operator()(unsigned int name) const {
  glDeleteVertexArrays(1, &name);
}
void GlProgramRelease::operator()(unsigned int name) const {
  glDeleteProgram(name);
}
void GlFramebufferObjectRelease::operator()(unsigned int name) const {
  glDeleteFramebuffers(1, &name);
}
void GlRenderbufferObjectRelease::operator()(unsigned int name) const {
  glDeleteRenderbuffers(1, &name);
}

GlTexture createTexture(unsigned int target) {
  GLuint name = 0;
  glCreateTextures(target, 1, &name);
  return GlTexture(name);
}
GlBuffer createBuffer() {
  GLuint name = 0;
  glCreateBuffers(1, &name);
  return GlBuffer(name);
}
GlVertexArray createVertexArray() {
  GLuint name = 0;
  glCreateVertexArrays(1, &name);
  return GlVertexArray(name);
}
GlFramebuffer createFramebuffer() {
  GLuint name = 0;
  glCreateFramebuffers(1, &name);
  return GlFramebuffer(name);
}
GlRenderbuffer createRenderbuffer() {
  GLuint name = 0;
  glCreateRenderbuffers(1, &name);
  return GlRenderbuffer(name);
}

GlTexture createTarget2D(unsigned int format, int width, int height) {
  GlTexture texture = createTexture(GL_TEXTURE_2D);
  glTextureStorage2D(texture.get(), 1, format, width, height);
  glTextureParameteri(texture.get(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTextureParameteri(texture.get(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  return texture;
}

GlTexture createTargetArray(unsigned int format, int size, int layers) {
  GlTexture texture = createTexture(GL_TEXTURE_2D_ARRAY);
  glTextureStorage3D(texture.get(), 1, format, size, size, layers);
  glTextureParameteri(texture.get(), GL_TEXTURE_MIN_FILTER, GL_NEAREST);
  glTextureParameteri(texture.get(), GL_TEXTURE_MAG_FILTER, GL_NEAREST);
  glTextureParameteri(texture.get(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
  glTextureParameteri(texture.get(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
  return texture;
}

namespace {

// Asked on every use, of the current context (contexts of one process may differ); the
// version string answers without a state query, and the extension list is searched only on
// a context older than 4.3.
bool debugLabels() {
  return epoxy_gl_version() >= 43 || epoxy_has_gl_extension("GL_KHR_debug");
}

}  // namespace

void labelGlObject(unsigned int identifier, unsigned int name, const std::string& label) {
  if (name == 0 || !debugLabels()) return;
  const std::string text = "ivshadow " + label;
  glObjectLabel(identifier, name, GLsizei(text.size()), text.c_str());
}

GlDebugGroup::GlDebugGroup(const std::string& name) : pushed_(debugLabels()) {
  if (!pushed_) return;
  const std::string text = "ivshadow " + name;
  glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 0, GLsizei(text.size()), text.c_str());
}

GlDebugGroup::~GlDebugGroup() {
  if (pushed_) glPopDebugGroup();
}

}  // namespace ivshadow
