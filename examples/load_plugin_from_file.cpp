// An Inventor program that does not link the plugin: it links Coin and libepoxy (GL and EGL
// entry points) only.
// Reading a scene that uses TransparentShadowGroup / DeepShadowLight / PeelingSeparator makes
// Coin load the plugin by those names from the library path (LD_LIBRARY_PATH=<plugin dir>),
// and the scene renders with its transparent, coloured shadows. It draws headlessly into a
// framebuffer object of a surfaceless EGL context and writes a binary PPM.
// Usage: LD_LIBRARY_PATH=build/lib load_plugin_from_file SCENE.iv OUT.ppm [WIDTHxHEIGHT]
#include <epoxy/egl.h>
#include <epoxy/gl.h>

#include <Inventor/SoDB.h>
#include <Inventor/SoInput.h>
#include <Inventor/actions/SoGLRenderAction.h>
#include <Inventor/elements/SoGLCacheContextElement.h>
#include <Inventor/misc/SoContextHandler.h>
#include <Inventor/nodes/SoSeparator.h>

#include <cstdio>
#include <fstream>
#include <vector>

namespace {

bool makeContext() {
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

}  // namespace

int main(int argc, char** argv) {
  if (argc < 3) {
    std::fprintf(stderr, "usage: load_plugin_from_file SCENE.iv OUT.ppm [WIDTHxHEIGHT]\n");
    return 2;
  }
  int width = 640, height = 480;
  if (argc > 3 && std::sscanf(argv[3], "%dx%d", &width, &height) != 2) return 2;

  SoDB::init();  // nothing else: the plugin comes in through the scene file
  SoInput input;
  if (!input.openFile(argv[1])) return 2;
  SoSeparator* root = SoDB::readAll(&input);
  if (root == nullptr) return 2;
  root->ref();

  if (!makeContext()) {
    std::fprintf(stderr, "load_plugin_from_file: no EGL context\n");
    return 3;
  }
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

  const uint32_t cacheContext = SoGLCacheContextElement::getUniqueCacheContext();
  const SbViewportRegion viewport(static_cast<short>(width), static_cast<short>(height));
  SoGLRenderAction action(viewport);
  action.setCacheContext(cacheContext);
  action.apply(root);
  glFinish();

  std::vector<unsigned char> pixels(std::size_t(width) * std::size_t(height) * 3);
  glPixelStorei(GL_PACK_ALIGNMENT, 1);
  glReadPixels(0, 0, width, height, GL_RGB, GL_UNSIGNED_BYTE, pixels.data());
  std::ofstream out(argv[2], std::ios::binary);
  out << "P6\n" << width << ' ' << height << "\n255\n";
  for (int y = height - 1; y >= 0; --y)  // GL rows are bottom-up, PPM rows top-down
    out.write(reinterpret_cast<const char*>(&pixels[std::size_t(y) * std::size_t(width) * 3]),
              std::streamsize(width) * 3);

  // Let the plugin free its GL resources while the context is still current.
  SoContextHandler::destructingContext(cacheContext);
  root->unref();
  std::printf("wrote %s\n", argv[2]);
  return out ? 0 : 1;
}
