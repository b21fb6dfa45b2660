#pragma once

#include "image/Image.h"

#include <Inventor/Qt/viewers/SoQtExaminerViewer.h>

#include <chrono>
#include <deque>
#include <functional>
#include <memory>

class SbVec2f;

namespace ivshadow {

class GlTimerQuery;

// Coin's examiner viewer that reports how long each frame took — wall clock until the GL
// finished it, and the GL_TIME_ELAPSED of the traversal — and can hand over the next
// frame's pixels, read before the buffer swap. A left-button drag with Ctrl held (or any
// left-button drag while the move-light mode is on) goes to the light-drag callback instead of
// turning the camera, so that the light can be moved without switching to Coin's pick mode.
class TimedExaminerViewer : public SoQtExaminerViewer {
  typedef SoQtExaminerViewer inherited;

 public:
  enum class LightDrag { Start, Move, Finish };

  explicit TimedExaminerViewer(QWidget* parent);
  ~TimedExaminerViewer() override;

  void onFrameTimed(std::function<void(double wallMs, double gpuMs)> callback);
  // The next redraw calls `callback` with what it drew; schedules that redraw.
  void captureNextFrame(std::function<void(const Image&)> callback);
  // Frames drawn so far.
  int framesDrawn() const { return frames_; }
  // Frames drawn in the last second, per second (or, after a single frame, the rate its time
  // allows).
  double framesPerSecond() const;
  // Whether the GL the viewer draws with is a software rasteriser (AUTO picks the tracers
  // there); false before the first frame.
  bool softwareRenderer() const { return softwareRenderer_; }

  // `callback` gets the drag's phase and the pointer's normalized position in the viewport;
  // it returns false at Start when there is no light to move (the drag then turns the camera).
  void onLightDrag(std::function<bool(LightDrag, const SbVec2f&)> callback) {
    lightDrag_ = std::move(callback);
  }
  // While on, every left-button drag in view mode moves the light.
  void setMoveLightMode(bool on) { moveLightMode_ = on; }

 protected:
  void actualRedraw() override;
  SbBool processSoEvent(const SoEvent* event) override;

 private:
  std::function<void(double, double)> frameTimed_;
  std::function<void(const Image&)> capture_;
  std::function<bool(LightDrag, const SbVec2f&)> lightDrag_;
  // Made at the first frame, when the viewer's GL context exists and is current.
  std::unique_ptr<GlTimerQuery> timer_;
  int frames_ = 0;
  double lastFrameMs_ = 0.0;
  std::deque<std::chrono::steady_clock::time_point> frameEnds_;
  bool softwareRenderer_ = false;
  bool moveLightMode_ = false;
  bool draggingLight_ = false;
};

}  // namespace ivshadow
