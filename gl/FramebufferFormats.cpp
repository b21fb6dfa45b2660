#include "gl/FramebufferFormats.h"

#include <epoxy/gl.h>

namespace ivshadow {
namespace {

GLint attachmentParameter(GLuint framebuffer, GLenum attachment, GLenum name) {
  GLint value = 0;
  glGetNamedFramebufferAttachmentParameteriv(framebuffer, attachment, name, &value);
  return value;
}

// The internal format of an attachment of a framebuffer object.
GLenum attachedFormat(GLuint framebuffer, GLenum attachment) {
  const GLint type =
      attachmentParameter(framebuffer, attachment, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE);
  const auto name =
      GLuint(attachmentParameter(framebuffer, attachment, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_NAME));
  GLint format = GL_NONE;
  if (type == GL_RENDERBUFFER)
    glGetNamedRenderbufferParameteriv(name, GL_RENDERBUFFER_INTERNAL_FORMAT, &format);
  else if (type == GL_TEXTURE)
    glGetTextureLevelParameteriv(
        name, attachmentParameter(framebuffer, attachment, GL_FRAMEBUFFER_ATTACHMENT_TEXTURE_LEVEL),
        GL_TEXTURE_INTERNAL_FORMAT, &format);
  return GLenum(format);
}

}  // namespace

unsigned int depthFormat(unsigned int framebuffer) {
  if (framebuffer != 0) return attachedFormat(framebuffer, GL_DEPTH_ATTACHMENT);
  // The default framebuffer names no format: the one its sizes say. Sizes are asked only of
  // buffers it has (GL raises an error for the others, into the application's error queue).
  if (attachmentParameter(0, GL_DEPTH, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE) == GL_NONE)
    return GL_NONE;
  GLint stencil = 0;
  if (attachmentParameter(0, GL_STENCIL, GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE) != GL_NONE)
    stencil = attachmentParameter(0, GL_STENCIL, GL_FRAMEBUFFER_ATTACHMENT_STENCIL_SIZE);
  if (attachmentParameter(0, GL_DEPTH, GL_FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE) == GL_FLOAT)
    return stencil > 0 ? GL_DEPTH32F_STENCIL8 : GL_DEPTH_COMPONENT32F;
  switch (attachmentParameter(0, GL_DEPTH, GL_FRAMEBUFFER_ATTACHMENT_DEPTH_SIZE)) {
    case 0:
      return GL_NONE;
    case 16:
      return GL_DEPTH_COMPONENT16;
    case 32:
      return GL_DEPTH_COMPONENT32;
    default:
      return stencil > 0 ? GL_DEPTH24_STENCIL8 : GL_DEPTH_COMPONENT24;
  }
}

unsigned int colourFormat(unsigned int framebuffer, unsigned int readBuffer) {
  if (readBuffer == GL_NONE) return GL_NONE;
  if (framebuffer != 0) return attachedFormat(framebuffer, GLenum(readBuffer));
  // The default framebuffer's buffers (GL_BACK, GL_FRONT, ...) share one format: the one
  // their sizes say, for the formats a window system offers.
  const auto size = [&](GLenum name) { return attachmentParameter(0, GLenum(readBuffer), name); };
  if (attachmentParameter(0, GLenum(readBuffer), GL_FRAMEBUFFER_ATTACHMENT_OBJECT_TYPE) == GL_NONE)
    return GL_NONE;
  const GLint red = size(GL_FRAMEBUFFER_ATTACHMENT_RED_SIZE);
  const GLint green = size(GL_FRAMEBUFFER_ATTACHMENT_GREEN_SIZE);
  const GLint blue = size(GL_FRAMEBUFFER_ATTACHMENT_BLUE_SIZE);
  const GLint alpha = size(GL_FRAMEBUFFER_ATTACHMENT_ALPHA_SIZE);
  if (size(GL_FRAMEBUFFER_ATTACHMENT_COMPONENT_TYPE) != GL_UNSIGNED_NORMALIZED) return GL_NONE;
  if (red == 8 && green == 8 && blue == 8) return alpha == 8 ? GL_RGBA8 : GL_RGB8;
  if (red == 10 && green == 10 && blue == 10) return alpha == 2 ? GL_RGB10_A2 : GL_RGB10;
  if (red == 5 && green == 6 && blue == 5 && alpha == 0) return GL_RGB565;
  return GL_NONE;
}

PixelTransfer depthTransfer(unsigned int format) {
  switch (format) {
    case GL_DEPTH24_STENCIL8:
      return {GL_DEPTH_STENCIL, GL_UNSIGNED_INT_24_8, 4};
    case GL_DEPTH32F_STENCIL8:
      return {GL_DEPTH_STENCIL, GL_FLOAT_32_UNSIGNED_INT_24_8_REV, 8};
    case GL_DEPTH_COMPONENT16:
      return {GL_DEPTH_COMPONENT, GL_UNSIGNED_SHORT, 2};
    case GL_DEPTH_COMPONENT24:
    case GL_DEPTH_COMPONENT32:
      return {GL_DEPTH_COMPONENT, GL_UNSIGNED_INT, 4};
    case GL_DEPTH_COMPONENT32F:
      return {GL_DEPTH_COMPONENT, GL_FLOAT, 4};
    default:
      return {};
  }
}

PixelTransfer colourTransfer(unsigned int format) {
  switch (format) {
    case GL_RGBA8:
      return {GL_RGBA, GL_UNSIGNED_BYTE, 4};
    case GL_RGB8:
      return {GL_RGB, GL_UNSIGNED_BYTE, 3};
    case GL_RGB10_A2:
    case GL_RGB10:
      return {GL_RGBA, GL_UNSIGNED_INT_2_10_10_10_REV, 4};
    case GL_RGB565:
      return {GL_RGB, GL_UNSIGNED_SHORT_5_6_5, 2};
    default:
      return {};
  }
}

}  // namespace ivshadow
