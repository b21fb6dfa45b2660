#include "headless/CoinOffscreenContexts.h"

#include "headless/EglHeadlessContext.h"

// epoxy's GL header must come before Coin's glue header, which includes GL/gl.h.
#include <epoxy/egl.h>
#include <epoxy/gl.h>

#include <Inventor/C/glue/gl.h>
#include <Inventor/errors/SoDebugError.h>

#include <dlfcn.h>

#include <memory>
#include <mutex>
#include <string>

namespace ivshadow {
namespace {

// GLX, reached only when the process already has it (the viewer draws through SoQt's GLX
// widget): a headless process must not load libGL's GLX for this. Null when absent.
struct GlxEntryPoints {
  using GetPointer = void* (*)();
  using GetDrawable = unsigned long (*)();
  using MakeCurrent = int (*)(void*, unsigned long, unsigned long, void*);
  GetPointer currentContext = nullptr, currentDisplay = nullptr;
  GetDrawable currentDraw = nullptr, currentRead = nullptr;
  MakeCurrent makeCurrent = nullptr;

  static const GlxEntryPoints& get() {
    static const GlxEntryPoints entries = [] {
      GlxEntryPoints e;
      if (dlsym(RTLD_DEFAULT, "glXMakeContextCurrent") == nullptr) return e;
      e.currentContext = reinterpret_cast<GetPointer>(dlsym(RTLD_DEFAULT, "glXGetCurrentContext"));
      e.currentDisplay = reinterpret_cast<GetPointer>(dlsym(RTLD_DEFAULT, "glXGetCurrentDisplay"));
      e.currentDraw = reinterpret_cast<GetDrawable>(dlsym(RTLD_DEFAULT, "glXGetCurrentDrawable"));
      e.currentRead =
          reinterpret_cast<GetDrawable>(dlsym(RTLD_DEFAULT, "glXGetCurrentReadDrawable"));
      e.makeCurrent = reinterpret_cast<MakeCurrent>(dlsym(RTLD_DEFAULT, "glXMakeContextCurrent"));
      return e;
    }();
    return entries;
  }
  bool present() const {
    return currentContext && currentDisplay && currentDraw && currentRead && makeCurrent;
  }
};

// The context current on the calling thread, through EGL or GLX, to be made current again.
struct CurrentContext {
  EGLDisplay display = EGL_NO_DISPLAY;
  EGLContext context = EGL_NO_CONTEXT;
  EGLSurface draw = EGL_NO_SURFACE;
  EGLSurface read = EGL_NO_SURFACE;
  void* glxDisplay = nullptr;
  void* glxContext = nullptr;
  unsigned long glxDraw = 0, glxRead = 0;

  static CurrentContext now() {
    CurrentContext c;
    c.display = eglGetCurrentDisplay();
    c.context = eglGetCurrentContext();
    c.draw = eglGetCurrentSurface(EGL_DRAW);
    c.read = eglGetCurrentSurface(EGL_READ);
    const GlxEntryPoints& glx = GlxEntryPoints::get();
    if (glx.present() && glx.currentContext() != nullptr) {
      c.glxContext = glx.currentContext();
      c.glxDisplay = glx.currentDisplay();
      c.glxDraw = glx.currentDraw();
      c.glxRead = glx.currentRead();
    }
    return c;
  }

  // libglvnd lets a thread have one current context across EGL and GLX: a GLX context must
  // be released before an EGL one is made current.
  void releaseGlx() const {
    if (glxContext != nullptr) GlxEntryPoints::get().makeCurrent(glxDisplay, 0, 0, nullptr);
  }

  void reinstate() const {
    if (context == EGL_NO_CONTEXT || glxContext != nullptr) {
      if (EGLDisplay current = eglGetCurrentDisplay(); current != EGL_NO_DISPLAY)
        eglMakeCurrent(current, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
      if (glxContext != nullptr)
        GlxEntryPoints::get().makeCurrent(glxDisplay, glxDraw, glxRead, glxContext);
      return;
    }
    eglMakeCurrent(display, draw, read, context);
  }
};

struct OffscreenContext {
  std::unique_ptr<EglHeadlessContext> context;
  // What was current on the thread before make_current, put back by reinstate_previous.
  CurrentContext previous;
};

cc_glglue_offscreen_data create(unsigned int, unsigned int) {
  // The size does not matter: the tessellator draws nothing, it only needs a current context.
  // Creating one makes it current, so the caller's context is put back straight away.
  const CurrentContext caller = CurrentContext::now();
  std::string error;
  auto offscreen = std::make_unique<OffscreenContext>();
  caller.releaseGlx();
  offscreen->context = EglHeadlessContext::create(error);
  caller.reinstate();
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
  offscreen->previous = CurrentContext::now();
  offscreen->previous.releaseGlx();
  return offscreen->context->makeCurrent() ? TRUE : FALSE;
}

void reinstatePrevious(cc_glglue_offscreen_data data) {
  static_cast<OffscreenContext*>(data)->previous.reinstate();
}

void destruct(cc_glglue_offscreen_data data) {
  // Coin destroys a shape's context with the shape, typically while a renderer's own context
  // is current; the EGL wrapper releases whatever is current when it dies, so the caller's
  // context is made current again afterwards.
  const CurrentContext caller = CurrentContext::now();
  auto* offscreen = static_cast<OffscreenContext*>(data);
  const bool wasCurrent = offscreen->context && offscreen->context->isCurrent();
  caller.releaseGlx();
  delete offscreen;
  if (!wasCurrent) caller.reinstate();
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
