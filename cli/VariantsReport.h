#pragma once

#include "cli/VariantManifest.h"
#include "scene_input/VariantsFile.h"

#include <string>
#include <vector>

namespace ivshadow {

// Writes DIR/variants.csv and DIR/index.html (docs/VARIANTS.md) for `variants` in their
// order, from each one's manifest (`outcomes[i]` belongs to `variants[i]`): the one writer of
// both a local run and variants-merge, so a sweep split over machines reports like one run.
void writeVariantsReports(const std::string& outputDir, const std::string& base,
                          const std::vector<Variant>& variants,
                          const std::vector<VariantManifest>& outcomes);

}  // namespace ivshadow
