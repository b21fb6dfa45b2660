#include "cli/RenderProcesses.h"

namespace ivshadow {

std::vector<std::string> RenderProcesses::command(const RenderOptions& options) {
  std::vector<std::string> command = {currentExecutable(),
                                      "render",
                                      options.scene,
                                      "-o",
                                      options.output,
                                      "--size",
                                      options.size,
                                      "--frames",
                                      std::to_string(options.frames)};
  if (!options.statsPath.empty()) command.insert(command.end(), {"--stats", options.statsPath});
  for (const std::string& assignment : options.assignments)
    command.insert(command.end(), {"--set", assignment});
  if (!options.transparency.empty())
    command.insert(command.end(), {"--transparency", options.transparency});
  return command;
}

void RenderProcesses::start(int id, const RenderOptions& options, const std::string& logPath) {
  children_.start(id, command(options), logPath);
}

std::optional<VariantRenders::Finished> RenderProcesses::waitAny() {
  const ChildProcesses::Finished done = children_.waitAny();
  return Finished{done.id, done.exitCode};
}

}  // namespace ivshadow
