#include "viewer/ScriptedDrag.h"

#include "ivshadow/SoDeepShadowLight.h"
#include "viewer/ViewerWindow.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>

namespace ivshadow {

ScriptedDrag::ScriptedDrag(ViewerWindow& window, int steps,
                           std::function<void(const std::string&)> done)
    : window_(window), steps_(steps), done_(std::move(done)) {
  quiet_.setSingleShot(true);
  quiet_.setInterval(kQuietMs);
  QObject::connect(&quiet_, &QTimer::timeout, [this] { finish({}); });
  giveUp_.setSingleShot(true);
  giveUp_.setInterval(kMaxWaitMs);
  QObject::connect(&giveUp_, &QTimer::timeout, [this] { finish({}); });
}

ScriptedDrag::~ScriptedDrag() {
  window_.onFrameDrawn(nullptr);
}

void ScriptedDrag::start() {
  SoDeepShadowLight* light = window_.lightDragger().light();
  if (light == nullptr) {
    finish("--drag-light: the scene has no DeepShadowLight for the dragger to drag");
    return;
  }
  start_ = location_ = light->location.getValue();
  // Two and a half dragger sizes: a tenth of the scene, a drag across part of it.
  radius_ = 2.5f * window_.lightDragger().size();
  window_.onFrameDrawn([this](double wallMs) { frameDrawn(wallMs); });
  clock_.start();
  step();
}

void ScriptedDrag::step() {
  ++stepsDone_;
  const float angle = 3.14159265f * float(stepsDone_) / float(steps_);
  location_ = start_ + radius_ * SbVec3f(std::cos(angle) - 1.0f, std::sin(angle), 0.0f);
  window_.lightDragger().dragTo(location_);
}

void ScriptedDrag::frameDrawn(double wallMs) {
  if (finished_) return;
  if (frameMs_.size() < std::size_t(steps_)) {
    frameMs_.push_back(wallMs);
    if (frameMs_.size() == std::size_t(steps_)) {
      seconds_ = double(clock_.nsecsElapsed()) * 1e-9;
      quiet_.start();
      giveUp_.start();
      return;
    }
    // The next step once Qt is back in its event loop, as the next mouse move would be.
    QTimer::singleShot(0, [this] { step(); });
    return;
  }
  ++framesAfter_;
  quiet_.start();
}

void ScriptedDrag::finish(const std::string& error) {
  if (finished_) return;
  finished_ = true;
  // Before the screenshot's own frame, which would refine a reduced picture itself.
  refinedFrames_ = window_.figures().shadows.tracerRefines;
  quiet_.stop();
  giveUp_.stop();
  window_.onFrameDrawn(nullptr);
  done_(error);
}

std::string ScriptedDrag::json() const {
  std::vector<double> sorted = frameMs_;
  std::sort(sorted.begin(), sorted.end());
  nlohmann::json out;
  out["frames"] = frameMs_.size();
  out["seconds"] = seconds_;
  out["frames_per_second"] = seconds_ > 0.0 ? double(frameMs_.size()) / seconds_ : 0.0;
  out["frame_ms_median"] = sorted.empty() ? 0.0 : sorted[sorted.size() / 2];
  out["frames_after"] = framesAfter_;
  out["refined_frames"] = refinedFrames_;
  out["light_location"] = {location_[0], location_[1], location_[2]};
  return out.dump();
}

}  // namespace ivshadow
