#pragma once

#include "gl/GlObject.h"
#include "ivshadow/Export.h"

namespace ivshadow {

struct IVSHADOW_INTERNAL GlQueryRelease {
  void operator()(unsigned int name) const;
};

// GPU time of the commands between begin() and end(), from a GL_TIME_ELAPSED query.
// One measurement at a time; elapsedMs() waits for the result.
class IVSHADOW_INTERNAL GlTimerQuery {
 public:
  GlTimerQuery();
  void begin();
  void end();
  double elapsedMs() const;

 private:
  GlObject<GlQueryRelease> query_;
};

}  // namespace ivshadow
