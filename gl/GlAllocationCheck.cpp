#include "gl/GlAllocationCheck.h"

#include <epoxy/gl.h>

#include <cstdio>
#include <cstdlib>
#include <sstream>

namespace ivshadow {
namespace {

struct ForcedFailures {
  bool texture = false;
  bool buffer = false;
  bool framebuffer = false;
  bool fragmentList = false;
  bool fragmentSlots = false;
};

// IVSHADOW_FAIL_GL, parsed once (a function-local static: safe when two contexts render on
// two threads). An unknown word is reported on stderr rather than ignored: a test whose knob
// was misspelt would otherwise pass without forcing anything.
const ForcedFailures& forced() {
  static const ForcedFailures failures = [] {
    ForcedFailures made;
    const char* text = std::getenv("IVSHADOW_FAIL_GL");
    if (text == nullptr) return made;
    std::istringstream words(text);
    std::string word;
    while (std::getline(words, word, ',')) {
      if (word == "texture")
        made.texture = true;
      else if (word == "buffer")
        made.buffer = true;
      else if (word == "framebuffer")
        made.framebuffer = true;
      else if (word == "list")
        made.fragmentList = true;
      else if (word == "slots")
        made.fragmentSlots = true;
      else if (!word.empty())
        std::fprintf(stderr,
                     "ivshadow: warning: IVSHADOW_FAIL_GL: '%s' is none of texture, buffer, "
                     "framebuffer, list, slots; ignored\n",
                     word.c_str());
    }
    return made;
  }();
  return failures;
}

bool isForced(GlAllocation kind) {
  const ForcedFailures& failures = forced();
  switch (kind) {
    case GlAllocation::Texture:
      return failures.texture;
    case GlAllocation::Buffer:
      return failures.buffer;
    case GlAllocation::Framebuffer:
      return failures.framebuffer;
    case GlAllocation::FragmentList:
      return failures.fragmentList;
    case GlAllocation::FragmentSlots:
      return failures.fragmentSlots;
  }
  return false;
}

std::string statusName(GLenum status) {
  switch (status) {
    case GL_FRAMEBUFFER_UNDEFINED:
      return "GL_FRAMEBUFFER_UNDEFINED";
    case GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT:
      return "GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT";
    case GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT:
      return "GL_FRAMEBUFFER_INCOMPLETE_MISSING_ATTACHMENT";
    case GL_FRAMEBUFFER_UNSUPPORTED:
      return "GL_FRAMEBUFFER_UNSUPPORTED";
    case GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE:
      return "GL_FRAMEBUFFER_INCOMPLETE_MULTISAMPLE";
    case GL_FRAMEBUFFER_INCOMPLETE_LAYER_TARGETS:
      return "GL_FRAMEBUFFER_INCOMPLETE_LAYER_TARGETS";
    default:
      return "status " + std::to_string(status);
  }
}

}  // namespace

void clearGlErrors() {
  while (glGetError() != GL_NO_ERROR) {
  }
}

std::string glErrorName(unsigned int error) {
  switch (error) {
    case GL_INVALID_ENUM:
      return "GL_INVALID_ENUM";
    case GL_INVALID_VALUE:
      return "GL_INVALID_VALUE";
    case GL_INVALID_OPERATION:
      return "GL_INVALID_OPERATION";
    case GL_INVALID_FRAMEBUFFER_OPERATION:
      return "GL_INVALID_FRAMEBUFFER_OPERATION";
    case GL_OUT_OF_MEMORY:
      return "GL_OUT_OF_MEMORY";
    case GL_STACK_OVERFLOW:
      return "GL_STACK_OVERFLOW";
    case GL_STACK_UNDERFLOW:
      return "GL_STACK_UNDERFLOW";
    default: {
      std::ostringstream text;
      text << "GL error 0x" << std::hex << error;
      return text.str();
    }
  }
}

std::string glAllocationError(GlAllocation kind) {
  GLenum first = GL_NO_ERROR;
  for (GLenum error = glGetError(); error != GL_NO_ERROR; error = glGetError())
    if (first == GL_NO_ERROR || error == GL_OUT_OF_MEMORY) first = error;
  if (first != GL_NO_ERROR) return glErrorName(first);
  if (isForced(kind)) return "GL_OUT_OF_MEMORY (forced by IVSHADOW_FAIL_GL)";
  return {};
}

std::string framebufferIncompleteness(unsigned int framebuffer) {
  const GLenum status = glCheckNamedFramebufferStatus(framebuffer, GL_DRAW_FRAMEBUFFER);
  if (status != GL_FRAMEBUFFER_COMPLETE) return statusName(status);
  if (isForced(GlAllocation::Framebuffer))
    return "GL_FRAMEBUFFER_INCOMPLETE_ATTACHMENT (forced by IVSHADOW_FAIL_GL)";
  return {};
}

}  // namespace ivshadow
