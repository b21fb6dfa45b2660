#pragma once

#include <string>

namespace ivshadow {

struct CompareOptions {
  std::string reference;  // A: the picture taken as right
  std::string candidate;  // B
  std::string diffPath;   // optional heat map
  std::string jsonPath;   // optional metrics as JSON
  int scale = 0;          // heat map: steps shown as white; 0 = the largest error
};

// `ivshadow compare A.png B.png`: RMSE, max abs error, PSNR and share of pixels off by more
// than 2/255, per channel and overall. Exit 0 (whatever the difference), 2 on bad input.
int runCompare(const CompareOptions& options);

}  // namespace ivshadow
