#pragma once

#include "cli/ChildProcesses.h"
#include "cli/VariantRenders.h"

namespace ivshadow {

// Each variant in an `ivshadow render` process of its own, `jobs` at a time: how `variants`
// rendered before its workers (IVSHADOW_VARIANTS_WORKERS=0), kept to compare the workers'
// pictures with and as a way round a GL driver that does not bear long-lived contexts.
class RenderProcesses : public VariantRenders {
 public:
  explicit RenderProcesses(int jobs) : children_(jobs) {}
  bool full() const override { return children_.full(); }
  bool empty() const override { return children_.empty(); }
  void start(int id, const RenderOptions& options, const std::string& logPath) override;
  std::optional<Finished> waitAny() override;
  void signalAll(int signal) override { children_.signalAll(signal); }

  // The `ivshadow render` command line of `options`.
  static std::vector<std::string> command(const RenderOptions& options);

 private:
  ChildProcesses children_;
};

}  // namespace ivshadow
