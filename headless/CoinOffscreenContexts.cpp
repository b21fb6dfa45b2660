#include "headless/CoinOffscreenContexts.h"

#include "headless/EglHeadlessContext.h"

// epoxy's GL header must come before Coin's glue header, which includes GL/gl.h.
#include <epoxy/egl.h>
#include <epoxy/gl.h>

#include <Inventor/C/glue/gl.h>
#include <Inventor/errors/SoDebugError.h>

#include <memory>
#include <mutex>
#include <string>

namespace ivshadow {
namespace {

struct OffscreenContext {
  std::unique_ptr<EglHeadlessContext> context;
  // What was current on the thread before make_current, put back by reinstate_previous.
  EGLDisplay previousDisplay = EGL_NO_DISPLAY;
  EGLContext previousContext = EGL_NO_CONTEXT;
  EGLSurface previousDraw = EGL_NO_SURFACE;
  EGLSurface previousRead = EGL_NO_SURFACE;
};

void restore(EGLDisplay display, EGLContext context, EGLSurface draw, EGLSurface read) {
  if (context == EGL_NO_CONTEXT) {
    if (EGLDisplay current = eglGetCurrentDisplay(); current != EGL_NO_DISPLAY)
      eglMakeCurrent(current, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    return;
  }
  eglMakeCurrent(display, draw, read, context);
}

cc_glglue_offscreen_data create(unsigned int, unsigned int) {
  // The size does not matter: the tessellator draws nothing, it only needs a current context.
  // Creating one makes it current, so the caller's context is put back straight away.
  const EGLDisplay display = eglGetCurrentDisplay();
  const EGLContext context = eglGetCurrentContext();
  const EGLSurface draw = eglGetCurrentSurface(EGL_DRAW), read = eglGetCurrentSurface(EGL_READ);
  std::string error;
  auto offscreen = std::make_unique<OffscreenContext>();
  offscreen->context = EglHeadlessContext::create(error);
  restore(display, context, draw, read);
  if (!offscreen->context) {
    SoDebugError::postWarning("ivshadow",
                              "no offscreen GL context for Coin (NURBS shapes "
                              "give no triangles): %s",
                              error.c_str());
    return nullptr;
  }
  return offscreen.release();
}

SbBool makeCurrent(cc_glglue_offscreen_data data) {
  auto* offscreen = static_cast<OffscreenContext*>(data);
  offscreen->previousDisplay = eglGetCurrentDisplay();
  offscreen->previousContext = eglGetCurrentContext();
  offscreen->previousDraw = eglGetCurrentSurface(EGL_DRAW);
  offscreen->previousRead = eglGetCurrentSurface(EGL_READ);
  return offscreen->context->makeCurrent() ? TRUE : FALSE;
}

void reinstatePrevious(cc_glglue_offscreen_data data) {
  auto* offscreen = static_cast<OffscreenContext*>(data);
  restore(offscreen->previousDisplay, offscreen->previousContext, offscreen->previousDraw,
          offscreen->previousRead);
}

void destruct(cc_glglue_offscreen_data data) {
  // Coin destroys a shape's context with the shape, typically while a renderer's own context
  // is current; the EGL wrapper releases whatever is current when it dies, so the caller's
  // context is made current again afterwards.
  const EGLDisplay display = eglGetCurrentDisplay();
  const EGLContext context = eglGetCurrentContext();
  const EGLSurface draw = eglGetCurrentSurface(EGL_DRAW), read = eglGetCurrentSurface(EGL_READ);
  auto* offscreen = static_cast<OffscreenContext*>(data);
  const bool wasCurrent = offscreen->context && offscreen->context->isCurrent();
  delete offscreen;
  if (!wasCurrent) restore(display, context, draw, read);
}

}  // namespace

void installCoinOffscreenContexts() {
  static std::once_flag once;
  std::call_once(once, [] {
    // Coin keeps the pointer: the table lives as long as the process.
    static cc_glglue_offscreen_cb_functions functions = {create, makeCurrent, reinstatePrevious,
                                                         destruct};
    cc_glglue_context_set_offscreen_cb_functions(&functions);
  });
}

}  // namespace ivshadow
