#include "viewer/TimedExaminerViewer.h"

#include "gl/GlCapabilities.h"
#include "gl/GlFrame.h"
#include "gl/GlTimerQuery.h"

#include <Inventor/events/SoLocation2Event.h>
#include <Inventor/events/SoMouseButtonEvent.h>

#include <QGLWidget>

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

double TimedExaminerViewer::framesPerSecond() const {
  if (frameEnds_.size() >= 2) {
    const double seconds =
        std::chrono::duration<double>(frameEnds_.back() - frameEnds_.front()).count();
    if (seconds > 0.0) return double(frameEnds_.size() - 1) / seconds;
  }
  return lastFrameMs_ > 0.0 ? 1000.0 / lastFrameMs_ : 0.0;
}

void TimedExaminerViewer::actualRedraw() {
  if (!timer_) {
    timer_ = std::make_unique<GlTimerQuery>();
    softwareRenderer_ = GlCapabilities::queryCurrent().isSoftwareRenderer();
  }
  const auto start = std::chrono::steady_clock::now();
  timer_->begin();
  inherited::actualRedraw();
  timer_->end();
  waitForGpu();
  const auto end = std::chrono::steady_clock::now();
  const double ms = std::chrono::duration<double, std::milli>(end - start).count();
  const double gpuMs = timer_->elapsedMs();
  if (capture_) {
    const SbVec2s size = getGLSize();
    auto callback = std::move(capture_);
    capture_ = nullptr;
    callback(captureReadFramebuffer(size[0], size[1]));
  }
  ++frames_;
  lastFrameMs_ = ms;
  // The rate is of the frames the user sees now: those of the last second.
  frameEnds_.push_back(end);
  while (end - frameEnds_.front() > std::chrono::seconds(1)) frameEnds_.pop_front();
  if (frameTimed_) frameTimed_(ms, gpuMs);
}

SbBool TimedExaminerViewer::processSoEvent(const SoEvent* event) {
  if (!lightDrag_) return inherited::processSoEvent(event);
  const SbVec2f position = event->getNormalizedPosition(getViewportRegion());
  // A drag ends with its button's release whatever the mode is by then (Esc turns to pick mode
  // mid-drag), so that the window lets the light go.
  if (draggingLight_ &&
      SoMouseButtonEvent::isButtonReleaseEvent(event, SoMouseButtonEvent::BUTTON1)) {
    draggingLight_ = false;
    lightDrag_(LightDrag::Finish, position);
    return TRUE;
  }
  if (!isViewing()) return inherited::processSoEvent(event);
  if (SoMouseButtonEvent::isButtonPressEvent(event, SoMouseButtonEvent::BUTTON1)) {
    // Ctrl alone: Ctrl+Shift is the examiner's zoom.
    const bool wanted = moveLightMode_ || (event->wasCtrlDown() && !event->wasShiftDown());
    if (wanted && lightDrag_(LightDrag::Start, position)) {
      draggingLight_ = true;
      return TRUE;
    }
  } else if (draggingLight_ && event->isOfType(SoLocation2Event::getClassTypeId())) {
    lightDrag_(LightDrag::Move, position);
    return TRUE;
  }
  return inherited::processSoEvent(event);
}

}  // namespace ivshadow
