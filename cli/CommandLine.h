#pragma once

#include "cli/CompareCommand.h"
#include "cli/ReferenceCommand.h"
#include "cli/RenderCommand.h"
#include "cli/TradeCommand.h"
#include "cli/VariantsCommand.h"
#include "cli/VariantsMerge.h"
#include "viewer/ViewerCommandLine.h"

#include <CLI/CLI.hpp>

#include <optional>
#include <string>
#include <vector>

namespace ivshadow {

// The `ivshadow` command line: every command, its options and its help, parsed into the
// commands' option structs, and the parsed command run. One object per command line (its
// options are bound to its members; it neither copies nor moves). Kept apart from main() so
// that fuzz/CommandLineFuzzer.cpp parses and runs exactly what users type.
class CommandLine {
 public:
  CommandLine();
  CommandLine(const CommandLine&) = delete;
  CommandLine& operator=(const CommandLine&) = delete;

  // Parses `argv`. Returns the exit status when parsing ends the run (--help and --version: 0;
  // an unknown command or option, a missing or malformed value: 2, said on stderr), or
  // nothing when a command is to be run.
  std::optional<int> parse(int argc, char** argv);
  // The parsed command's name ("render", "view", ...), empty before parse().
  std::string command() const;
  // Runs the parsed command and returns its exit status (`view` replaces this process with
  // the viewer's, cli/ViewerProcess.h).
  int run();

 private:
  CLI::App app_;
  RenderOptions render_;
  VariantsOptions variants_;
  VariantsMergeOptions merge_;
  ReferenceCommandOptions reference_;
  TradeOptions trade_;
  CompareOptions compare_;
  ViewerOptions view_;
  CLI::App* renderCommand_ = nullptr;
  CLI::App* variantsCommand_ = nullptr;
  CLI::App* mergeCommand_ = nullptr;
  CLI::App* referenceCommand_ = nullptr;
  CLI::App* tradeCommand_ = nullptr;
  CLI::App* compareCommand_ = nullptr;
  CLI::App* workerCommand_ = nullptr;
  CLI::Option* bounceOption_ = nullptr;
  CLI::App* viewCommand_ = nullptr;
  // The arguments after `view`, passed on to the viewer program as they were typed.
  std::vector<std::string> viewArguments_;
};

}  // namespace ivshadow
