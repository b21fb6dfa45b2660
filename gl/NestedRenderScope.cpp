#include "gl/NestedRenderScope.h"

#include <epoxy/gl.h>

namespace ivshadow {

NestedRenderScope::NestedRenderScope() {
  glGetIntegerv(GL_CURRENT_PROGRAM, &program_);
  glGetIntegerv(GL_VERTEX_ARRAY_BINDING, &vertexArray_);
  glGetIntegerv(GL_ARRAY_BUFFER_BINDING, &arrayBuffer_);
  glGetIntegerv(GL_DRAW_FRAMEBUFFER_BINDING, &drawFramebuffer_);
  glGetIntegerv(GL_READ_FRAMEBUFFER_BINDING, &readFramebuffer_);
  glGetIntegerv(GL_ACTIVE_TEXTURE, &activeTexture_);
  glGetIntegerv(GL_MATRIX_MODE, &matrixMode_);
  // Read rather than pushed: the projection stack may be only two deep, and Coin's own
  // traversal may push onto it.
  glGetFloatv(GL_PROJECTION_MATRIX, projection_.data());
  glGetFloatv(GL_MODELVIEW_MATRIX, modelView_.data());
  // Coin's texture transforms go to the active unit's matrix; the first unit's is saved.
  glActiveTexture(GL_TEXTURE0);
  glGetFloatv(GL_TEXTURE_MATRIX, texture_.data());
  glActiveTexture(GLenum(activeTexture_));
  glPushAttrib(GL_ALL_ATTRIB_BITS);
  glPushClientAttrib(GL_CLIENT_ALL_ATTRIB_BITS);
}

NestedRenderScope::~NestedRenderScope() {
  glPopClientAttrib();
  glPopAttrib();
  glMatrixMode(GL_PROJECTION);
  glLoadMatrixf(projection_.data());
  glMatrixMode(GL_MODELVIEW);
  glLoadMatrixf(modelView_.data());
  glActiveTexture(GL_TEXTURE0);
  glMatrixMode(GL_TEXTURE);
  glLoadMatrixf(texture_.data());
  glMatrixMode(GLenum(matrixMode_));
  glActiveTexture(GLenum(activeTexture_));
  glUseProgram(GLuint(program_));
  glBindVertexArray(GLuint(vertexArray_));
  glBindBuffer(GL_ARRAY_BUFFER, GLuint(arrayBuffer_));
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, GLuint(drawFramebuffer_));
  glBindFramebuffer(GL_READ_FRAMEBUFFER, GLuint(readFramebuffer_));
}

}  // namespace ivshadow
