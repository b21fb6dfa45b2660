#include "tests/gl/GlCallCounter.h"

#include <epoxy/gl.h>

namespace ivshadow::test {
namespace {

long queryCount = 0;
long lookupCount = 0;
long waitCount = 0;
long drawCount = 0;
long blitCount = 0;
std::vector<std::string> groups;

decltype(epoxy_glGetIntegerv) realGetIntegerv;
decltype(epoxy_glGetIntegeri_v) realGetIntegeri_v;
decltype(epoxy_glGetBooleanv) realGetBooleanv;
decltype(epoxy_glGetFloatv) realGetFloatv;
decltype(epoxy_glIsEnabled) realIsEnabled;
decltype(epoxy_glGetUniformLocation) realGetUniformLocation;
decltype(epoxy_glGetQueryObjectuiv) realGetQueryObjectuiv;
decltype(epoxy_glGetQueryObjectui64v) realGetQueryObjectui64v;
decltype(epoxy_glDrawArrays) realDrawArrays;
decltype(epoxy_glBlitNamedFramebuffer) realBlitNamedFramebuffer;
decltype(epoxy_glPushDebugGroup) realPushDebugGroup;

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

void GLAPIENTRY countDrawArrays(GLenum mode, GLint first, GLsizei count) {
  ++drawCount;
  realDrawArrays(mode, first, count);
}
void GLAPIENTRY countBlitNamedFramebuffer(GLuint from, GLuint to, GLint fromX0, GLint fromY0,
                                          GLint fromX1, GLint fromY1, GLint toX0, GLint toY0,
                                          GLint toX1, GLint toY1, GLbitfield mask, GLenum filter) {
  ++blitCount;
  realBlitNamedFramebuffer(from, to, fromX0, fromY0, fromX1, fromY1, toX0, toY0, toX1, toY1, mask,
                           filter);
}

// Counts a read of `query`'s result that GL does not have yet (asking is no wait).
void countWait(GLuint query, GLenum name) {
  if (name != GL_QUERY_RESULT) return;
  GLuint available = GL_FALSE;
  realGetQueryObjectuiv(query, GL_QUERY_RESULT_AVAILABLE, &available);
  if (available != GL_TRUE) ++waitCount;
}
void GLAPIENTRY countGetQueryObjectuiv(GLuint query, GLenum name, GLuint* data) {
  countWait(query, name);
  realGetQueryObjectuiv(query, name, data);
}
void GLAPIENTRY countGetQueryObjectui64v(GLuint query, GLenum name, GLuint64* data) {
  countWait(query, name);
  realGetQueryObjectui64v(query, name, data);
}

void GLAPIENTRY countPushDebugGroup(GLenum source, GLuint id, GLsizei length,
                                    const GLchar* message) {
  groups.emplace_back(message,
                      length < 0 ? std::char_traits<char>::length(message) : std::size_t(length));
  realPushDebugGroup(source, id, length, message);
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
  hook(epoxy_glDrawArrays, realDrawArrays, &countDrawArrays, on);
  hook(epoxy_glBlitNamedFramebuffer, realBlitNamedFramebuffer, &countBlitNamedFramebuffer, on);
  hook(epoxy_glGetQueryObjectuiv, realGetQueryObjectuiv, &countGetQueryObjectuiv, on);
  hook(epoxy_glGetQueryObjectui64v, realGetQueryObjectui64v, &countGetQueryObjectui64v, on);
  hook(epoxy_glPushDebugGroup, realPushDebugGroup, &countPushDebugGroup, on);
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
  // Draws nothing (no vertices) and blits nothing (no framebuffer has the buffers of an empty
  // mask to copy): both only resolve their pointers.
  glDrawArrays(GL_POINTS, 0, 0);
  glBlitNamedFramebuffer(0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, GL_NEAREST);
  glGetError();
  if (debugOutput) glEnable(GL_DEBUG_OUTPUT);
  // A query of its own, finished, resolves the two result readers.
  GLuint query = 0;
  glGenQueries(1, &query);
  glQueryCounter(query, GL_TIMESTAMP);
  glFinish();
  GLuint available = GL_FALSE;
  GLuint64 time = 0;
  glGetQueryObjectuiv(query, GL_QUERY_RESULT_AVAILABLE, &available);
  glGetQueryObjectui64v(query, GL_QUERY_RESULT, &time);
  glDeleteQueries(1, &query);
  glPushDebugGroup(GL_DEBUG_SOURCE_APPLICATION, 0, -1, "resolves the pointer");
  glPopDebugGroup();
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
long GlCallCounter::resultWaits() const {
  return waitCount;
}
const std::vector<std::string>& GlCallCounter::debugGroups() const {
  return groups;
}
long GlCallCounter::draws() const {
  return drawCount;
}
long GlCallCounter::blits() const {
  return blitCount;
}
void GlCallCounter::reset() {
  queryCount = 0;
  lookupCount = 0;
  drawCount = 0;
  blitCount = 0;
  waitCount = 0;
  groups.clear();
}

}  // namespace ivshadow::test
