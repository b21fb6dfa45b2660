#pragma once

#include "cli/RenderCommand.h"

#include <memory>
#include <optional>
#include <string>

namespace ivshadow {

// How `ivshadow variants` renders its variants, a few at a time: each as `ivshadow render`
// would, its stderr in a log file of its own, with the exit status that command would have.
class VariantRenders {
 public:
  struct Finished {
    int id = 0;            // as given to start()
    int exitCode = -1;     // -1 when the render was killed by a signal
    bool retried = false;  // its first render's process died, and it was rendered again
  };

  // `jobs` at a time by long-lived workers (RenderWorkers); one `ivshadow render` process per
  // variant (RenderProcesses) when the environment sets IVSHADOW_VARIANTS_WORKERS=0.
  static std::unique_ptr<VariantRenders> create(int jobs);
  virtual ~VariantRenders() = default;

  // Whether `jobs` renders are under way.
  virtual bool full() const = 0;
  // Whether none is.
  virtual bool empty() const = 0;
  // Starts rendering `options` (stderr to `logPath`); throws std::runtime_error when no
  // process can be started.
  virtual void start(int id, const RenderOptions& options, const std::string& logPath) = 0;
  // Waits for a render to end. Nothing when a signal came first, so that the caller can see
  // to an interrupt.
  virtual std::optional<Finished> waitAny() = 0;
  // Sends `signal` to every process rendering; nothing is started or retried after it.
  virtual void signalAll(int signal) = 0;
};

}  // namespace ivshadow
