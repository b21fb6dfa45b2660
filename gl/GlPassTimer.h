#pragma once

#include "gl/GlTimerQuery.h"

namespace ivshadow {

// GPU time of one pass inside Coin's traversal, from two GL_TIMESTAMP queries. Unlike a
// GL_TIME_ELAPSED query (GlTimerQuery) it may run while another timer query is active: the
// headless renderer and the viewer time whole frames with one. Made and used with its GL
// context current.
//
// Reading a result the GPU has not reached stalls the CPU until it does, so results are
// waited for only while someone reads the timings (setWaitForResults, which the statistics'
// pass timing sets). Otherwise a measurement is read when the next one starts, if
// GL_QUERY_RESULT_AVAILABLE says GL has it by then (the frame before has usually finished):
// asking right after the pass would find nothing, and make some drivers (llvmpipe among them)
// flush the frame's commands early.
class GlPassTimer {
 public:
  GlPassTimer();
  // A measurement still unread when the next starts is resolved first if GL has its result
  // (the frame before has usually finished by then), and dropped if not.
  void start();
  void stop();
  // The last measurement's time while results are waited for; otherwise the latest one read,
  // 0 before the first.
  double elapsedMs() const;

  // Whether elapsedMs waits for the GPU, for every pass timer of the process.
  static void setWaitForResults(bool wait);
  static bool waitsForResults();

 private:
  // Reads the pending measurement into lastMs_ when `wait` or when GL has its result.
  void resolve(bool wait) const;

  GlObject<GlQueryRelease> start_;
  GlObject<GlQueryRelease> stop_;
  // What reading caches: a const read may resolve the pending measurement.
  mutable bool pending_ = false;  // stopped and not read yet
  mutable double lastMs_ = 0.0;
};

}  // namespace ivshadow
