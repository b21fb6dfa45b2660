#pragma once

#include "viewer/ViewerOptions.h"

namespace CLI {
class App;
}

namespace ivshadow {

// The viewer's options, shared by `ivshadow-viewer` and `ivshadow view`.
void addViewerOptions(CLI::App& app, ViewerOptions& options);

// Makes CLI11's parse errors read as the project's other errors: "PROGRAM: error: WHAT", then
// which --help tells the options (the subcommand's, when one was given).
void useProjectErrorFormat(CLI::App& app);

}  // namespace ivshadow
