#pragma once

#include <Inventor/SbVec3f.h>

#include <QElapsedTimer>
#include <QTimer>

#include <functional>
#include <string>
#include <vector>

namespace ivshadow {

class ViewerWindow;

// `--drag-light N`: drags the light dragger as a user would, N steps along half a circle
// about the light's place, one step after each frame drawn, and times the frames; then
// waits until the viewer has drawn nothing for a second (a traced group's refined frame,
// which the group asks for itself, comes in that time) and reports.
class ScriptedDrag {
 public:
  // Quiet: no frame drawn for this long ends the wait after the drag; at most kMaxWait.
  static constexpr int kQuietMs = 1000;
  static constexpr int kMaxWaitMs = 20000;

  // `done` gets an empty string, or what stopped the drag.
  ScriptedDrag(ViewerWindow& window, int steps, std::function<void(const std::string&)> done);
  ~ScriptedDrag();
  ScriptedDrag(const ScriptedDrag&) = delete;
  ScriptedDrag& operator=(const ScriptedDrag&) = delete;

  // Starts with the next step; the window's dragger must be on a light.
  void start();
  // The drag's figures as one JSON object (frames, seconds, frames_per_second,
  // frame_ms_median, frames_after, refined_frames, light_location).
  std::string json() const;

 private:
  void frameDrawn(double wallMs);
  void step();
  void finish(const std::string& error);

  ViewerWindow& window_;
  int steps_;
  std::function<void(const std::string&)> done_;
  int stepsDone_ = 0;
  int framesAfter_ = 0;
  int refinedFrames_ = 0;  // traced groups' refined frames when the wait ended
  bool finished_ = false;
  SbVec3f start_;
  SbVec3f location_;
  float radius_ = 0.0f;
  QElapsedTimer clock_;
  double seconds_ = 0.0;
  std::vector<double> frameMs_;
  QTimer quiet_;
  QTimer giveUp_;
};

}  // namespace ivshadow
