#pragma once

#include <string>
#include <vector>

namespace ivshadow {

// Runs `ivshadow view`: replaces this process with ivshadow-viewer from the folder ivshadow
// runs from, given `arguments` (those after `view`, already checked by ivshadow's own parse of
// the same options). ivshadow links neither Qt nor SoQt, so that headless renders, batch nodes
// and the GPU kit load no GUI libraries; the viewer binary is the one that does. Returns only
// when the viewer cannot be started: 1, said on stderr with the path tried.
int runViewerProcess(const std::vector<std::string>& arguments);

}  // namespace ivshadow
