#pragma once

#include "viewer/ViewerApplication.h"

namespace CLI {
class App;
}

namespace ivshadow {

// The viewer's options, shared by `ivshadow-viewer` and (to be) `ivshadow view`.
void addViewerOptions(CLI::App& app, ViewerOptions& options);

}  // namespace ivshadow
