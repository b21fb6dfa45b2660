#include "gl/GlFramebufferTarget.h"

#include "gl/GlFrame.h"

#include <epoxy/gl.h>

namespace ivshadow {
namespace {

GLuint makeRenderbuffer(GLenum format, int width, int height) {
  GLuint name = 0;
  glGenRenderbuffers(1, &name);
  glBindRenderbuffer(GL_RENDERBUFFER, name);
  glRenderbufferStorage(GL_RENDERBUFFER, format, width, height);
  glBindRenderbuffer(GL_RENDERBUFFER, 0);
  return name;
}

}  // namespace

GlFramebufferTarget GlFramebufferTarget::create(int width, int height, std::string& error) {
  GLint maxSize = 0;
  glGetIntegerv(GL_MAX_RENDERBUFFER_SIZE, &maxSize);
  if (width < 1 || height < 1 || width > maxSize || height > maxSize) {
    error = "render target " + std::to_string(width) + "x" + std::to_string(height) +
            " is outside the GL limit of 1.." + std::to_string(maxSize) + " pixels per side";
    return {};
  }
  GlFramebufferTarget target;
  target.width_ = width;
  target.height_ = height;
  target.colour_ = GlRenderbuffer(makeRenderbuffer(GL_RGBA8, width, height));
  target.depthStencil_ = GlRenderbuffer(makeRenderbuffer(GL_DEPTH24_STENCIL8, width, height));
  GLuint fbo = 0;
  glGenFramebuffers(1, &fbo);
  target.framebuffer_ = GlFramebuffer(fbo);
  glBindFramebuffer(GL_FRAMEBUFFER, fbo);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER,
                            target.colour_.get());
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER,
                            target.depthStencil_.get());
  const GLenum status = glCheckFramebufferStatus(GL_FRAMEBUFFER);
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  if (status != GL_FRAMEBUFFER_COMPLETE) {
    error = "glCheckFramebufferStatus reported the render target incomplete (status " +
            std::to_string(status) + ")";
    return {};
  }
  return target;
}

void GlFramebufferTarget::bindAndClear(float red, float green, float blue, float alpha) {
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.get());
  glDrawBuffer(GL_COLOR_ATTACHMENT0);
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  glViewport(0, 0, width_, height_);
  glClearColor(red, green, blue, alpha);
  glClearDepth(1.0);
  glClearStencil(0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  // Coin assumes its caller enabled depth testing (SoGLDepthBufferElement only records it;
  // SoOffscreenRenderer and the SoQt widgets enable it before rendering). Without it, back
  // faces drawn later overwrite front faces.
  glEnable(GL_DEPTH_TEST);
}

Image GlFramebufferTarget::read() const {
  glBindFramebuffer(GL_READ_FRAMEBUFFER, framebuffer_.get());
  glReadBuffer(GL_COLOR_ATTACHMENT0);
  return captureReadFramebuffer(width_, height_);
}

}  // namespace ivshadow
