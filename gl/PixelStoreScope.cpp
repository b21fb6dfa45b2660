#include "gl/PixelStoreScope.h"

#include <epoxy/gl.h>

#include <initializer_list>

namespace ivshadow {

PixelStoreScope::PixelStoreScope() {
  glPushClientAttrib(GL_CLIENT_PIXEL_STORE_BIT);
  glGetIntegerv(GL_PIXEL_PACK_BUFFER_BINDING, &packBuffer_);
  glGetIntegerv(GL_PIXEL_UNPACK_BUFFER_BINDING, &unpackBuffer_);
  glBindBuffer(GL_PIXEL_PACK_BUFFER, 0);
  glBindBuffer(GL_PIXEL_UNPACK_BUFFER, 0);
  for (const GLenum alignment : {GL_PACK_ALIGNMENT, GL_UNPACK_ALIGNMENT})
    glPixelStorei(alignment, 4);
  for (const GLenum zero :
       {GL_PACK_ROW_LENGTH, GL_PACK_SKIP_ROWS, GL_PACK_SKIP_PIXELS, GL_PACK_IMAGE_HEIGHT,
        GL_PACK_SKIP_IMAGES, GL_UNPACK_ROW_LENGTH, GL_UNPACK_SKIP_ROWS, GL_UNPACK_SKIP_PIXELS,
        GL_UNPACK_IMAGE_HEIGHT, GL_UNPACK_SKIP_IMAGES})
    glPixelStorei(zero, 0);
}

PixelStoreScope::~PixelStoreScope() {
  glBindBuffer(GL_PIXEL_PACK_BUFFER, GLuint(packBuffer_));
  glBindBuffer(GL_PIXEL_UNPACK_BUFFER, GLuint(unpackBuffer_));
  glPopClientAttrib();
}

}  // namespace ivshadow
