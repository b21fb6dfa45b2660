#pragma once

#include <string>
#include <vector>

namespace ivshadow {

struct VariantsOptions {
  std::string base;          // the scene every variant starts from
  std::string variantsFile;  // docs/VARIANTS.md
  std::string outputDir;
  std::string size = "800x600";
  int frames = 3;
  int jobs = 1;
  // Past one machine (docs/VARIANTS.md, "On a cluster").
  std::string shard;              // --shard K/N: the variants whose index is K modulo N
  std::vector<std::string> only;  // --only NAME: just these variants
  bool list = false;              // --list: print a line per variant and its command
  std::string slurmDir;           // --slurm DIR: write the sbatch scripts there
  int shards = 0;                 // --shards: array tasks (0: 8, at most one per variant)
  int limit = 0;                  // --limit: array tasks at once (0: no limit)
};

// `ivshadow variants`: renders each variant as `ivshadow render` would, by long-lived worker
// processes (up to `jobs` at a time; cli/VariantRenders.h) to DIR/NAME.png with its manifest
// DIR/manifests/NAME.json and writes DIR/variants.csv and DIR/index.html. A variant that fails
// is reported with its line in the variants file and skipped; one whose manifest is current is
// kept from an earlier run. With --shard or --only it renders that part only and leaves the
// reports to variants-merge; --list and --slurm print or write the commands of the parts
// instead of rendering. Exit 0 when every variant rendered, 2 when the inputs are bad or some
// variant had bad input, 1 otherwise.
int runVariants(const VariantsOptions& options);

}  // namespace ivshadow
