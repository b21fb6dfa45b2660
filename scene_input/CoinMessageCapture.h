#pragma once

#include <Inventor/errors/SoError.h>

#include <string>
#include <vector>

namespace ivshadow {

// While alive, collects the messages Coin posts through SoReadError and SoDebugError instead
// of letting Coin print them, so callers can report them once, with file and line, in their
// own words. Restores the previous handlers when destroyed. Not thread-safe (neither is Coin's
// error handling).
class CoinMessageCapture {
 public:
  struct Message {
    bool isError = false;  // SoReadError or SoDebugError::ERROR; otherwise a warning/info
    std::string text;      // Coin's message without its "Coin read error:" preamble
    std::string file;      // where Coin said it occurred, if it did
    int line = 0;          // 1-based line, 0 when unknown
    std::string raw;       // Coin's whole message as it would have printed it
  };

  CoinMessageCapture();
  ~CoinMessageCapture();
  CoinMessageCapture(const CoinMessageCapture&) = delete;
  CoinMessageCapture& operator=(const CoinMessageCapture&) = delete;

  const std::vector<Message>& messages() const { return messages_; }
  // The first error, or an empty message when there was none.
  Message firstError() const;
  // Passes on every captured message except those whose text contains `benign`: to the
  // capture this one is nested in, if any, otherwise to stderr.
  void forwardExcept(const std::string& benign) const;

 private:
  std::vector<Message> messages_;
  SoErrorCB* previousReadHandler_ = nullptr;
  void* previousReadData_ = nullptr;
  SoErrorCB* previousDebugHandler_ = nullptr;
  void* previousDebugData_ = nullptr;
};

}  // namespace ivshadow
