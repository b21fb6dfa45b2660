#pragma once

#include "cli/VariantManifest.h"
#include "cli/VariantsPlan.h"

#include <string>
#include <vector>

namespace ivshadow {

struct VariantsMergeOptions {
  std::string outputDir;
  bool statusOnly = false;  // --status: print the counts, write nothing
};

// Where a sweep stands, from its plan and the manifests its shards wrote: a variant is done
// when its manifest says ok for the plan's hash and its picture exists, failed when its
// manifest says it failed, pending otherwise (no manifest, or one of other inputs).
struct SweepState {
  std::vector<VariantManifest> outcomes;  // one per plan variant; pending ones marked kPending
  int done = 0;
  int failed = 0;
  int pending = 0;
  int badInput = 0;  // failed with exit status 2: an unknown node or field, a bad value

  // What a manifest that cannot be read (empty, cut short, wrongly typed) means: for a merge
  // or --status an error naming it (exit 2: a report from it would be wrong); for a run that
  // renders, a variant to render again, which replaces the manifest.
  enum class BrokenManifest { Refuse, RenderAgain };

  static SweepState collect(const VariantsPlan& plan, const std::string& outputDir,
                            BrokenManifest broken = BrokenManifest::Refuse);
  // 0 when every variant is done, 2 when every other one had bad input, 1 otherwise.
  int exitStatus() const;
};

// Writes the reports of `state` and prints each variant that is not done with its message on
// stderr: what a local run and variants-merge both end with.
void reportSweep(const VariantsPlan& plan, const SweepState& state, const std::string& outputDir);

// `ivshadow variants-merge DIR`: DIR/variants.csv and DIR/index.html from every shard's
// manifests, the same files one local run writes; with --status only "done D, failed F,
// pending P of T variants".
int runVariantsMerge(const VariantsMergeOptions& options);

}  // namespace ivshadow
