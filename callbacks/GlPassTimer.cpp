#include "callbacks/GlPassTimer.h"

#include <epoxy/gl.h>

namespace ivshadow {

GlPassTimer::GlPassTimer() {
  GLuint names[2] = {0, 0};
  glGenQueries(2, names);
  start_ = GlObject<GlQueryRelease>(names[0]);
  stop_ = GlObject<GlQueryRelease>(names[1]);
}

void GlPassTimer::start() {
  glQueryCounter(start_.get(), GL_TIMESTAMP);
}

void GlPassTimer::stop() {
  glQueryCounter(stop_.get(), GL_TIMESTAMP);
  measured_ = true;
}

double GlPassTimer::elapsedMs() const {
  if (!measured_) return 0.0;
  GLuint64 begin = 0, end = 0;
  glGetQueryObjectui64v(start_.get(), GL_QUERY_RESULT, &begin);
  glGetQueryObjectui64v(stop_.get(), GL_QUERY_RESULT, &end);
  return end > begin ? static_cast<double>(end - begin) * 1e-6 : 0.0;
}

}  // namespace ivshadow
