#include "viewer/TimedExaminerViewer.h"

#include "callbacks/GlFrame.h"
#include "callbacks/GlTimerQuery.h"

#include <QGLWidget>

#include <chrono>

namespace ivshadow {

TimedExaminerViewer::TimedExaminerViewer(QWidget* parent) : inherited(parent) {}

TimedExaminerViewer::~TimedExaminerViewer() {
  // The query belongs to the viewer's context, which need not be current any more.
  auto* gl = qobject_cast<QGLWidget*>(getGLWidget());
  if (timer_ && gl != nullptr && gl->isValid()) {
    gl->makeCurrent();
    timer_.reset();
  } else {
    // Without its context the query cannot be deleted; it goes with the context.
    static_cast<void>(timer_.release());
  }
}

void TimedExaminerViewer::onFrameTimed(std::function<void(double, double)> callback) {
  frameTimed_ = std::move(callback);
}

void TimedExaminerViewer::captureNextFrame(std::function<void(const Image&)> callback) {
  capture_ = std::move(callback);
  scheduleRedraw();
}

void TimedExaminerViewer::actualRedraw() {
  if (!timer_) timer_ = std::make_unique<GlTimerQuery>();
  const auto start = std::chrono::steady_clock::now();
  timer_->begin();
  inherited::actualRedraw();
  timer_->end();
  waitForGpu();
  const double ms =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  const double gpuMs = timer_->elapsedMs();
  if (capture_) {
    const SbVec2s size = getGLSize();
    auto callback = std::move(capture_);
    capture_ = nullptr;
    callback(captureReadFramebuffer(size[0], size[1]));
  }
  ++frames_;
  if (frameTimed_) frameTimed_(ms, gpuMs);
}

}  // namespace ivshadow
