#pragma once

#include "cli/ProgressBar.h"
#include "cli/VariantManifest.h"
#include "cli/VariantRenders.h"
#include "cli/VariantsCommand.h"
#include "cli/VariantsPlan.h"

#include <nlohmann/json.hpp>

#include <atomic>
#include <chrono>
#include <cstddef>
#include <memory>
#include <set>
#include <string>
#include <vector>

namespace ivshadow {

// The renders of one `ivshadow variants` run: the variants it has left to render, started up
// to --jobs at a time (cli/VariantRenders.h), each one's manifest written as its render ends
// (a failed variant's error names its line in the variants file), with a progress bar. Once
// `interrupted` is set no render starts, the running ones are sent SIGINT, and a render the
// signal ended leaves no manifest and no scratch file, so that a rerun renders it.
class SweepRun {
 public:
  // `todo`: indices into the plan's variants.
  SweepRun(const VariantsOptions& options, const VariantsPlan& plan, std::vector<std::size_t> todo,
           const std::atomic<bool>& interrupted);

  // Renders every variant of `todo`, or after an interrupt waits for the renders under way.
  void renderAll();

  const std::vector<std::size_t>& todo() const { return todo_; }
  int rendered() const { return rendered_; }
  // 0 when no render failed, 2 when every failed one had bad input, 1 otherwise.
  int exitStatus() const;

 private:
  // Keeps every worker busy: called again as soon as a render ends, so that the next variant
  // renders while this process files the one that ended.
  void startRenders();
  // A render that ended on its own: its manifest written, its scratch files removed, counted.
  void file(const VariantRenders::Finished& done);
  // A render the interrupt ended: not failed, so no manifest, and nothing of it left behind.
  void discard(std::size_t i) const;
  VariantManifest manifestOf(std::size_t i, const VariantRenders::Finished& done);
  // The settings the render's log says did nothing, each said on stderr once for the sweep.
  nlohmann::json idleSettings(std::size_t i);
  // The variant's render's scratch file `what` (".stats.json", ".log") in the output directory.
  std::string scratch(std::size_t i, const char* what) const;
  void removeScratch(std::size_t i) const;

  const VariantsOptions& options_;
  const VariantsPlan& plan_;
  const std::vector<Variant>& variants_;
  const std::vector<std::size_t> todo_;
  const std::atomic<bool>& interrupted_;
  const std::string host_;
  ProgressBar bar_;
  const std::unique_ptr<VariantRenders> renders_;
  std::vector<std::chrono::steady_clock::time_point> started_;
  std::size_t next_ = 0;  // in todo_: the next variant to start
  int finished_ = 0, rendered_ = 0, failed_ = 0, badInput_ = 0;
  bool stopping_ = false;           // the renders were sent the interrupt
  std::set<std::string> saidIdle_;  // the idle settings said so far
};

}  // namespace ivshadow
