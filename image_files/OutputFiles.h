#pragma once

#include "image/Image.h"

#include <atomic>
#include <functional>
#include <string>
#include <vector>

namespace ivshadow {

// The outputs of one command, written all or none: a command that fails half-way (a full
// disk under its statistics, an interruption) must not leave the picture it wrote before,
// since its exit status says that nothing was made. Each output is written under a temporary
// name beside it (AtomicFile) and renamed only once every output has been written; outputs
// written in place (a device or a pipe, which nothing can take back) come after the
// temporaries, so that a failure of those leaves nothing written at all.
class OutputFiles {
 public:
  // Writes a whole file to the path it is given (the temporary, or the device itself) and
  // throws, naming the output, when it cannot.
  using Writer = std::function<void(const std::string& file)>;

  void add(const std::string& path, Writer write);
  // `image` is written in the format its name asks for (imageFormatFor) and must live until
  // commit().
  void addImage(const std::string& path, const Image& image);
  void addText(const std::string& path, std::string text);

  // Writes every output and renames them into place. Throws what a writer throws, leaving no
  // output; returns false, leaving none either, when `cancel` is set once everything was
  // written (an interruption during the writes). A rename that fails after others succeeded
  // cannot undo those (renames within one directory fail only when the directory changed
  // under the command).
  bool commit(const std::atomic<bool>* cancel = nullptr);
  // As commit(), for a process that leaves SIGINT, SIGTERM and SIGHUP to their default action
  // (the viewer): one that arrives during the writes is held until every output is in place,
  // or none is, and then delivered, so the process ends as the signal says without a
  // temporary left behind.
  void commitWhole();

 private:
  struct Output {
    std::string path;
    Writer write;
  };
  std::vector<Output> outputs_;
};

}  // namespace ivshadow
