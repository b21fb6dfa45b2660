#include "tests/gl/GlCallCounter.h"

#include <epoxy/gl.h>

namespace ivshadow::test {
namespace {

long queryCount = 0;
long lookupCount = 0;

decltype(epoxy_glGetIntegerv) realGetIntegerv;
decltype(epoxy_glGetIntegeri_v) realGetIntegeri_v;
decltype(epoxy_glGetBooleanv) realGetBooleanv;
decltype(epoxy_glGetFloatv) realGetFloatv;
decltype(epoxy_glIsEnabled) realIsEnabled;
decltype(epoxy_glGetUniformLocation) realGetUniformLocation;

void GLAPIENTRY countGetIntegerv(GLenum name, GLint* data) {
  ++queryCount;
  realGetIntegerv(name, data);
}
void GLAPIENTRY countGetIntegeri_v(GLenum name, GLuint index, GLint* data) {
  ++queryCount;
  realGetIntegeri_v(name, index, data);
}
void GLAPIENTRY countGetBooleanv(GLenum name, GLboolean* data) {
  ++queryCount;
  realGetBooleanv(name, data);
}
void GLAPIENTRY countGetFloatv(GLenum name, GLfloat* data) {
  ++queryCount;
  realGetFloatv(name, data);
}
GLboolean GLAPIENTRY countIsEnabled(GLenum cap) {
  ++queryCount;
  return realIsEnabled(cap);
}
GLint GLAPIENTRY countGetUniformLocation(GLuint program, const GLchar* name) {
  ++lookupCount;
  return realGetUniformLocation(program, name);
}

// Puts `counting` in epoxy's `pointer`, keeping what it held in `real`; or puts `real` back.
template <typename Function>
void hook(Function& pointer, Function& real, Function counting, bool on) {
  if (on) {
    real = pointer;
    pointer = counting;
  } else {
    pointer = real;
  }
}

void hookAll(bool on) {
  hook(epoxy_glGetIntegerv, realGetIntegerv, &countGetIntegerv, on);
  hook(epoxy_glGetIntegeri_v, realGetIntegeri_v, &countGetIntegeri_v, on);
  hook(epoxy_glGetBooleanv, realGetBooleanv, &countGetBooleanv, on);
  hook(epoxy_glGetFloatv, realGetFloatv, &countGetFloatv, on);
  hook(epoxy_glIsEnabled, realIsEnabled, &countIsEnabled, on);
  hook(epoxy_glGetUniformLocation, realGetUniformLocation, &countGetUniformLocation, on);
}

}  // namespace

GlCallCounter::GlCallCounter() {
  // The first call through each pointer resolves it (epoxy then overwrites the pointer); the
  // queries are harmless and their results unused.
  GLint integers[4] = {};
  GLboolean booleans[4] = {};
  GLfloat floats[4] = {};
  glGetIntegerv(GL_VIEWPORT, integers);
  glGetIntegeri_v(GL_SHADER_STORAGE_BUFFER_BINDING, 0, integers);
  glGetBooleanv(GL_COLOR_WRITEMASK, booleans);
  glGetFloatv(GL_COLOR_CLEAR_VALUE, floats);
  const bool debugOutput = glIsEnabled(GL_DEBUG_OUTPUT);
  // No program may exist yet: a look-up in program 0 resolves the pointer with an error
  // (GL_INVALID_VALUE), kept from KHR_debug and taken back from glGetError.
  glDisable(GL_DEBUG_OUTPUT);
  glGetUniformLocation(0, "");
  glGetError();
  if (debugOutput) glEnable(GL_DEBUG_OUTPUT);
  hookAll(true);
  reset();
}

GlCallCounter::~GlCallCounter() {
  hookAll(false);
}

long GlCallCounter::queries() const {
  return queryCount;
}
long GlCallCounter::uniformLookups() const {
  return lookupCount;
}
void GlCallCounter::reset() {
  queryCount = 0;
  lookupCount = 0;
}

}  // namespace ivshadow::test
