#pragma once

#include "image/Image.h"

#include <Inventor/Qt/viewers/SoQtExaminerViewer.h>

#include <functional>
#include <memory>

namespace ivshadow {

class GlTimerQuery;

// Coin's examiner viewer that reports how long each frame took — wall clock until the GL
// finished it, and the GL_TIME_ELAPSED of the traversal — and can hand over the next
// frame's pixels, read before the buffer swap.
class TimedExaminerViewer : public SoQtExaminerViewer {
  typedef SoQtExaminerViewer inherited;

 public:
  explicit TimedExaminerViewer(QWidget* parent);
  ~TimedExaminerViewer() override;

  void onFrameTimed(std::function<void(double wallMs, double gpuMs)> callback);
  // The next redraw calls `callback` with what it drew; schedules that redraw.
  void captureNextFrame(std::function<void(const Image&)> callback);
  // Frames drawn so far.
  int framesDrawn() const { return frames_; }

 protected:
  void actualRedraw() override;

 private:
  std::function<void(double, double)> frameTimed_;
  std::function<void(const Image&)> capture_;
  // Made at the first frame, when the viewer's GL context exists and is current.
  std::unique_ptr<GlTimerQuery> timer_;
  int frames_ = 0;
};

}  // namespace ivshadow
