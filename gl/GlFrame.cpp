#include "gl/GlFrame.h"

#include <epoxy/gl.h>

namespace ivshadow {

Image captureReadFramebuffer(int width, int height) {
  Image image(width, height);
  glPushClientAttrib(GL_CLIENT_PIXEL_STORE_BIT);
  GLint packBuffer = 0;
  glGetIntegerv(GL_PIXEL_PACK_BUFFER_BINDING, &packBuffer);
  glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glPixelStorei(GL_PACK_ROW_LENGTH, 0);
  glPixelStorei(GL_PACK_SKIP_ROWS, 0);
  glPixelStorei(GL_PACK_SKIP_PIXELS, 0);
  glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, image.data());
  glBindBuffer(GL_PIXEL_PACK_BUFFER, static_cast<GLuint>(packBuffer));
  glPopClientAttrib();
  image.flipVertically();
  return image;
}

void waitForGpu() {
  glFinish();
}

}  // namespace ivshadow
