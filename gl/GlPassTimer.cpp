#include "gl/GlPassTimer.h"

#include <epoxy/gl.h>

#include <atomic>

namespace ivshadow {
namespace {

std::atomic<bool> waitForResults{false};

}  // namespace

GlPassTimer::GlPassTimer() {
  GLuint names[2] = {0, 0};
  glGenQueries(2, names);
  start_ = GlObject<GlQueryRelease>(names[0]);
  stop_ = GlObject<GlQueryRelease>(names[1]);
}

void GlPassTimer::start() {
  if (pending_) resolve(false);
  pending_ = false;
  glQueryCounter(start_.get(), GL_TIMESTAMP);
}

void GlPassTimer::stop() {
  glQueryCounter(stop_.get(), GL_TIMESTAMP);
  pending_ = true;
}

double GlPassTimer::elapsedMs() const {
  if (pending_ && waitsForResults()) resolve(true);
  return lastMs_;
}

void GlPassTimer::resolve(bool wait) const {
  if (!wait) {
    // The stop timestamp comes after the start one: once it is available, both are.
    GLuint available = GL_FALSE;
    glGetQueryObjectuiv(stop_.get(), GL_QUERY_RESULT_AVAILABLE, &available);
    if (available != GL_TRUE) return;
  }
  GLuint64 begin = 0, end = 0;
  glGetQueryObjectui64v(start_.get(), GL_QUERY_RESULT, &begin);
  glGetQueryObjectui64v(stop_.get(), GL_QUERY_RESULT, &end);
  lastMs_ = end > begin ? static_cast<double>(end - begin) * 1e-6 : 0.0;
  pending_ = false;
}

void GlPassTimer::setWaitForResults(bool wait) {
  waitForResults = wait;
}

bool GlPassTimer::waitsForResults() {
  return waitForResults;
}

}  // namespace ivshadow
