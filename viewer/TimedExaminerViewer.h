#pragma once

#include "image/Image.h"

#include <Inventor/Qt/viewers/SoQtExaminerViewer.h>

#include <functional>

namespace ivshadow {

// Coin's examiner viewer that reports how long each frame took (until the GL finished it) and
// can hand over the next frame's pixels, read before the buffer swap.
class TimedExaminerViewer : public SoQtExaminerViewer {
  typedef SoQtExaminerViewer inherited;

 public:
  explicit TimedExaminerViewer(QWidget* parent);

  void onFrameTimed(std::function<void(double milliseconds)> callback);
  // The next redraw calls `callback` with what it drew; schedules that redraw.
  void captureNextFrame(std::function<void(const Image&)> callback);
  // Frames drawn so far.
  int framesDrawn() const { return frames_; }

 protected:
  void actualRedraw() override;

 private:
  std::function<void(double)> frameTimed_;
  std::function<void(const Image&)> capture_;
  int frames_ = 0;
};

}  // namespace ivshadow
