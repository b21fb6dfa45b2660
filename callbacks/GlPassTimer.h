#pragma once

#include "callbacks/GlTimerQuery.h"

namespace ivshadow {

// GPU time of one pass inside Coin's traversal, from two GL_TIMESTAMP queries. Unlike a
// GL_TIME_ELAPSED query (GlTimerQuery) it may run while another timer query is active: the
// headless renderer and the viewer time whole frames with one. Made and used with its GL
// context current.
class GlPassTimer {
 public:
  GlPassTimer();
  void start();
  void stop();
  // Waits for both timestamps; 0 before the first start()/stop().
  double elapsedMs() const;

 private:
  GlObject<GlQueryRelease> start_;
  GlObject<GlQueryRelease> stop_;
  bool measured_ = false;
};

}  // namespace ivshadow
