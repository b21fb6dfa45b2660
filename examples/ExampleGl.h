#pragma once

// What the headless examples do before and while Coin draws, as an application would write it:
// a GL 4.5 compatibility context without a window (Mesa's surfaceless EGL platform, through
// libepoxy), a framebuffer object to draw into, and one SoGLRenderAction. The plugin's own
// headless renderer is a tool of the project, not part of its installed API.
#include <epoxy/egl.h>
#include <epoxy/gl.h>

#include <Inventor/SbViewportRegion.h>
#include <Inventor/actions/SoGLRenderAction.h>
#include <Inventor/elements/SoGLCacheContextElement.h>
#include <Inventor/nodes/SoNode.h>

#include <cstdint>

namespace example {

inline bool makeContext() {
  auto getPlatformDisplay = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(
      eglGetProcAddress("eglGetPlatformDisplayEXT"));
  if (!getPlatformDisplay) return false;
  EGLDisplay display =
      getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
  if (display == EGL_NO_DISPLAY || !eglInitialize(display, nullptr, nullptr)) return false;
  if (!eglBindAPI(EGL_OPENGL_API)) return false;
  const EGLint attributes[] = {EGL_CONTEXT_MAJOR_VERSION,
                               4,
                               EGL_CONTEXT_MINOR_VERSION,
                               5,
                               EGL_CONTEXT_OPENGL_PROFILE_MASK,
                               EGL_CONTEXT_OPENGL_COMPATIBILITY_PROFILE_BIT,
                               EGL_NONE};
  EGLContext context = eglCreateContext(display, EGL_NO_CONFIG_KHR, EGL_NO_CONTEXT, attributes);
  return context != EGL_NO_CONTEXT &&
         eglMakeCurrent(display, EGL_NO_SURFACE, EGL_NO_SURFACE, context);
}

// Binds a new RGBA8 framebuffer object with depth and stencil, width x height, and clears it.
inline void bindFramebuffer(int width, int height) {
  GLuint framebuffer = 0, colour = 0, depth = 0;
  glGenRenderbuffers(1, &colour);
  glBindRenderbuffer(GL_RENDERBUFFER, colour);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_RGBA8, width, height);
  glGenRenderbuffers(1, &depth);
  glBindRenderbuffer(GL_RENDERBUFFER, depth);
  glRenderbufferStorage(GL_RENDERBUFFER, GL_DEPTH24_STENCIL8, width, height);
  glGenFramebuffers(1, &framebuffer);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_COLOR_ATTACHMENT0, GL_RENDERBUFFER, colour);
  glFramebufferRenderbuffer(GL_FRAMEBUFFER, GL_DEPTH_STENCIL_ATTACHMENT, GL_RENDERBUFFER, depth);
  glViewport(0, 0, width, height);
  glClearColor(0, 0, 0, 0);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT | GL_STENCIL_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);  // Coin expects whoever applies the action to enable it
}

// Renders `root` into the bound framebuffer and waits for the GL. Returns the cache context
// used, for SoContextHandler::destructingContext while the context is still current.
inline std::uint32_t render(SoNode* root, int width, int height) {
  const std::uint32_t cacheContext = SoGLCacheContextElement::getUniqueCacheContext();
  const SbViewportRegion viewport(static_cast<short>(width), static_cast<short>(height));
  SoGLRenderAction action(viewport);
  action.setCacheContext(cacheContext);
  action.apply(root);
  glFinish();
  return cacheContext;
}

}  // namespace example
