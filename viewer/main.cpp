#include "viewer/ViewerApplication.h"
#include "viewer/ViewerCommandLine.h"

#include <CLI/CLI.hpp>

int main(int argc, char** argv) {
  CLI::App app{"ivshadow-viewer: view Open Inventor scenes with transparent shadows",
               "ivshadow-viewer"};
  ivshadow::ViewerOptions options;
  ivshadow::addViewerOptions(app, options);
  ivshadow::useProjectErrorFormat(app);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    const int status = app.exit(error);
    return status == 0 ? 0 : 2;
  }
  return ivshadow::runViewer(options, argv[0]);
}
