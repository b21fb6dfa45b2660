#include "viewer/ViewerApplication.h"

#include <CLI/CLI.hpp>

int main(int argc, char** argv) {
  CLI::App app{"ivshadow-viewer: view Open Inventor scenes with transparent shadows",
               "ivshadow-viewer"};
  ivshadow::ViewerOptions options;
  app.add_option("scene", options.scene, "Open Inventor scene file (.iv)");
  app.add_option("--screenshot", options.screenshot, "Save the first frame to this PNG and quit");
  app.add_option("--size", options.size, "Viewer area WIDTHxHEIGHT")->capture_default_str();
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    const int status = app.exit(error);
    return status == 0 ? 0 : 2;
  }
  return ivshadow::runViewer(options, argv[0]);
}
