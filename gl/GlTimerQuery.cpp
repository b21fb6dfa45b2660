#include "gl/GlTimerQuery.h"

#include <epoxy/gl.h>

namespace ivshadow {

void GlQueryRelease::operator()(unsigned int name) const {
  glDeleteQueries(1, &name);
}

GlTimerQuery::GlTimerQuery() {
  GLuint name = 0;
  glGenQueries(1, &name);
  query_ = GlObject<GlQueryRelease>(name);
}

void GlTimerQuery::begin() {
  glBeginQuery(GL_TIME_ELAPSED, query_.get());
}

void GlTimerQuery::end() {
  glEndQuery(GL_TIME_ELAPSED);
}

double GlTimerQuery::elapsedMs() const {
  GLuint64 nanoseconds = 0;
  glGetQueryObjectui64v(query_.get(), GL_QUERY_RESULT, &nanoseconds);
  return static_cast<double>(nanoseconds) * 1e-6;
}

}  // namespace ivshadow
