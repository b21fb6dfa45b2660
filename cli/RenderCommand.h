#pragma once

#include <string>
#include <vector>

namespace ivshadow {

struct RenderOptions {
  std::string scene;
  std::string output;
  std::string size = "800x600";
  int frames = 1;
  std::string statsPath;
  std::vector<std::string> assignments;  // NAME.field=VALUE
  std::string transparency;              // empty: Coin's default
};

// `ivshadow render`: exit 0 on success, 2 on bad input, 3 when no GL context can be made,
// 1 on any other failure. Never leaves a partial output file.
int runRender(const RenderOptions& options);

}  // namespace ivshadow
