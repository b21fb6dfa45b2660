#pragma once

#include <string>

namespace ivshadow {

struct VariantsOptions {
  std::string base;          // the scene every variant starts from
  std::string variantsFile;  // docs/VARIANTS.md
  std::string outputDir;
  std::string size = "800x600";
  int frames = 3;
  int jobs = 1;
};

// `ivshadow variants`: renders each variant with `ivshadow render` in a child process (up to
// `jobs` at a time) to DIR/NAME.png and writes DIR/variants.csv and DIR/index.html. A variant
// that fails is reported with its line in the variants file and skipped. Exit 0 when every
// variant rendered, 2 when the inputs are bad or some variant had bad input, 1 otherwise.
int runVariants(const VariantsOptions& options);

}  // namespace ivshadow
