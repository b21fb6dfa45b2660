#include "cli/CommandLine.h"

int main(int argc, char** argv) {
  ivshadow::CommandLine commandLine;
  if (const std::optional<int> status = commandLine.parse(argc, argv)) return *status;
  return commandLine.run();
}
