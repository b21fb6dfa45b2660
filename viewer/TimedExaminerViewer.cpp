#include "viewer/TimedExaminerViewer.h"

#include "callbacks/GlFrame.h"

#include <chrono>

namespace ivshadow {

TimedExaminerViewer::TimedExaminerViewer(QWidget* parent) : inherited(parent) {}

void TimedExaminerViewer::onFrameTimed(std::function<void(double)> callback) {
  frameTimed_ = std::move(callback);
}

void TimedExaminerViewer::captureNextFrame(std::function<void(const Image&)> callback) {
  capture_ = std::move(callback);
  scheduleRedraw();
}

void TimedExaminerViewer::actualRedraw() {
  const auto start = std::chrono::steady_clock::now();
  inherited::actualRedraw();
  waitForGpu();
  const double ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  if (capture_) {
    const SbVec2s size = getGLSize();
    auto callback = std::move(capture_);
    capture_ = nullptr;
    callback(captureReadFramebuffer(size[0], size[1]));
  }
  ++frames_;
  if (frameTimed_) frameTimed_(ms);
}

}  // namespace ivshadow
