#include "cli/ViewerProcess.h"

#include "cli/ChildProcesses.h"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <iostream>

namespace ivshadow {
namespace {

std::string viewerBesideThisProgram() {
  // Installed and built alike, the two programs lie in one folder (bin/).
  try {
    return (std::filesystem::path(currentExecutable()).parent_path() / "ivshadow-viewer").string();
  } catch (const std::exception&) {
    return "ivshadow-viewer";
  }
}

}  // namespace

int runViewerProcess(const std::vector<std::string>& arguments) {
  const std::string viewer = viewerBesideThisProgram();
  std::vector<char*> argv;
  argv.push_back(const_cast<char*>(viewer.c_str()));
  for (const std::string& argument : arguments) argv.push_back(const_cast<char*>(argument.c_str()));
  argv.push_back(nullptr);
  // What this process wrote must reach its streams before another program takes them over.
  std::cout.flush();
  std::fflush(nullptr);
  execv(viewer.c_str(), argv.data());
  std::cerr << "ivshadow: error: view runs the viewer, " << viewer
            << ", which could not be started: " << std::strerror(errno)
            << " (is ivshadow-viewer installed beside ivshadow?)\n";
  return 1;
}

}  // namespace ivshadow
