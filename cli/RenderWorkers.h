#pragma once

#include "cli/VariantRenders.h"

#include <sys/types.h>

#include <vector>

namespace ivshadow {

// Up to `jobs` long-lived `ivshadow variants-worker` processes (cli/VariantsWorker.h), each
// rendering variant after variant in its own GL context. They are started as the first
// variants need them and end when this object dies. A worker that dies while it renders (a
// crash, an abort, a kill) is started again and the variant retried once in the new worker,
// so that a variant fails only if it fails on its own in a fresh process, as it would have
// in a render process of its own; a worker that dies between variants is started again when
// one needs it.
class RenderWorkers : public VariantRenders {
 public:
  explicit RenderWorkers(int jobs);
  ~RenderWorkers() override;
  RenderWorkers(const RenderWorkers&) = delete;
  RenderWorkers& operator=(const RenderWorkers&) = delete;

  bool full() const override;
  bool empty() const override;
  void start(int id, const RenderOptions& options, const std::string& logPath) override;
  std::optional<Finished> waitAny() override;
  void signalAll(int signal) override;

 private:
  struct Worker {
    pid_t pid = -1;   // -1: no process
    int socket = -1;  // its stdin and stdout
    std::string received;
    bool last = false;  // said it ends after its answer: no more requests for it
    int id = -1;        // the variant it renders; -1 when idle
    std::string request;
    std::string logPath;
    bool retried = false;
  };
  void spawn(Worker& worker);
  // Sends the worker its request, its log emptied first (a render process's log was created
  // empty as it started): a worker that dies before it opens the log leaves no words of an
  // earlier try there.
  void send(Worker& worker);
  // Waits for the worker's process to end and closes its socket: the exit status (-1 when
  // a signal killed it).
  int reap(Worker& worker);
  // A line the worker sent, or its end: the variant it finished, if any.
  std::optional<Finished> readFrom(Worker& worker);

  std::vector<Worker> workers_;
  std::string executable_;
  bool stopping_ = false;
};

}  // namespace ivshadow
