#include "cli/VariantsMerge.h"

#include "cli/ExitStatus.h"
#include "cli/VariantsReport.h"
#include "scene/InputError.h"

#include <filesystem>
#include <iostream>

namespace ivshadow {

SweepState SweepState::collect(const VariantsPlan& plan, const std::string& outputDir,
                               BrokenManifest broken) {
  SweepState state;
  for (std::size_t i = 0; i < plan.variants.size(); ++i) {
    const Variant& variant = plan.variants[i];
    std::optional<VariantManifest> manifest;
    try {
      manifest = VariantManifest::read(outputDir, variant.name);
    } catch (const InputError&) {
      if (broken == BrokenManifest::Refuse) throw;
    }
    std::error_code ec;
    const bool current = manifest && manifest->hash == plan.hashes[i];
    if (current && manifest->ok() &&
        std::filesystem::is_regular_file(outputDir + "/" + variant.name + ".png", ec)) {
      ++state.done;
      state.outcomes.push_back(*manifest);
    } else if (current && !manifest->ok()) {
      ++state.failed;
      state.badInput += manifest->exitCode == 2 ? 1 : 0;
      state.outcomes.push_back(*manifest);
    } else {
      ++state.pending;
      VariantManifest pending;
      pending.variant = variant.name;
      pending.exitCode = VariantManifest::kPending;
      pending.error = plan.variantsFile + ":" + std::to_string(variant.line) + ": error: variant " +
                      variant.name +
                      ": not rendered yet (no shard has reported it for these inputs)";
      state.outcomes.push_back(pending);
    }
  }
  return state;
}

int SweepState::exitStatus() const {
  if (failed == 0 && pending == 0) return 0;
  return pending == 0 && badInput == failed ? 2 : 1;
}

void reportSweep(const VariantsPlan& plan, const SweepState& state, const std::string& outputDir) {
  writeVariantsReports(outputDir, plan.base, plan.variants, state.outcomes);
  for (const VariantManifest& outcome : state.outcomes)
    if (!outcome.ok()) std::cerr << outcome.error << '\n';
}

int runVariantsMerge(const VariantsMergeOptions& options) {
  return withExitStatus([&] {
    const VariantsPlan plan = VariantsPlan::read(options.outputDir);
    const SweepState state = SweepState::collect(plan, options.outputDir);
    const std::string counts = "done " + std::to_string(state.done) + ", failed " +
                               std::to_string(state.failed) + ", pending " +
                               std::to_string(state.pending) + " of " +
                               std::to_string(plan.variants.size()) + " variants";
    if (options.statusOnly) {
      std::cout << options.outputDir << ": " << counts << '\n';
      for (const VariantManifest& outcome : state.outcomes)
        if (!outcome.ok() && outcome.exitCode != VariantManifest::kPending)
          std::cout << "  " << outcome.error << '\n';
      return 0;
    }
    reportSweep(plan, state, options.outputDir);
    std::cout << "merged " << options.outputDir << ": " << counts
              << " (variants.csv, index.html)\n";
    return state.exitStatus();
  });
}

}  // namespace ivshadow
