#pragma once

#include "cli/RenderCommand.h"

#include <optional>
#include <string>

namespace ivshadow {

// `ivshadow variants-worker` (hidden; started by `ivshadow variants`, cli/RenderWorkers.h):
// renders variant after variant through one RenderSession, so that a sweep pays for a
// process, an EGL context and Coin's start once per worker rather than once per variant.
//
// Each line on stdin is a request, a JSON object (workerRequest); each is answered by one
// line on stdout, {"exit": STATUS, "last": BOOL}, STATUS being what `ivshadow render` with
// the request's options would have exited with. While a request renders, stderr goes to its
// log file (created or emptied), as a render process's did, and stdout nowhere; between
// requests stderr goes where the worker's went. After a failure other than bad input the
// worker answers with "last": true and exits: a render that failed midway may have left the
// GL context or Coin in any state, and the next variant must not inherit it. After a render
// that logged anything but Coin's infos, the next render reads its scene afresh
// (RenderSession::forgetScene). At the end of stdin it exits 0.
int runVariantsWorker();

// The line that asks a worker for the render `options` describe, its stderr to `logPath`.
std::string workerRequest(const RenderOptions& options, const std::string& logPath);

// A worker's answer: the render's exit status, and whether the worker ends after it.
struct WorkerAnswer {
  int exitCode = 1;
  bool last = false;
  // Nothing when `line` is not an answer.
  static std::optional<WorkerAnswer> parse(const std::string& line);
};

}  // namespace ivshadow
