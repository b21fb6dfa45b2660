#include "cli/VariantsCommand.h"

#include "cli/ChildProcesses.h"
#include "cli/ExitStatus.h"
#include "cli/InterruptGuard.h"
#include "cli/OutputDirectory.h"
#include "cli/RenderMemory.h"
#include "cli/SlurmScript.h"
#include "cli/SweepRun.h"
#include "cli/VariantManifest.h"
#include "cli/VariantShard.h"
#include "cli/VariantsMerge.h"
#include "cli/VariantsPlan.h"
#include "image_files/AtomicFile.h"
#include "image_files/CommandPaths.h"
#include "image_files/ImageSize.h"
#include "image_files/MemoryBudget.h"
#include "ivshadow/IvShadowInit.h"
#include "scene/InputError.h"
#include "scene_input/SceneLoader.h"
#include "scene_input/VariantsFile.h"

#include <Inventor/nodes/SoSeparator.h>

#include <algorithm>
#include <atomic>
#include <filesystem>
#include <iostream>

namespace ivshadow {
namespace {

// The variants this run renders: those of its shard, and of those the ones --only names.
std::vector<std::size_t> selectVariants(const VariantsOptions& options,
                                        const std::vector<Variant>& variants) {
  const VariantShard shard =
      options.shard.empty() ? VariantShard{} : VariantShard::parse(options.shard);
  for (const std::string& name : options.only) {
    bool known = false;
    for (const Variant& variant : variants) known = known || variant.name == name;
    if (!known)
      throw InputError("--only " + name + ": error: " + options.variantsFile +
                       " has no variant of that name (--list lists them)");
  }
  std::vector<std::size_t> selected;
  for (std::size_t i = 0; i < variants.size(); ++i) {
    bool named = options.only.empty();
    for (const std::string& name : options.only) named = named || variants[i].name == name;
    if (named && shard.contains(i)) selected.push_back(i);
  }
  return selected;
}

// The command that renders a part of this sweep: the same inputs and settings, so the same
// plan and hashes, whichever machine runs it.
std::vector<std::string> partCommand(const VariantsOptions& options, const std::string& base,
                                     const std::string& variantsFile,
                                     const std::string& outputDir) {
  return {
      currentExecutable(), "variants", base,         variantsFile, "-o",
      outputDir,           "--size",   options.size, "--frames",   std::to_string(options.frames)};
}

// The sweep's files (docs/VARIANTS.md) must not name its inputs: a variants file kept in the
// output directory as variants.csv, or a base scene there, would be replaced by the report.
void checkOutputPaths(const VariantsOptions& options, const std::vector<Variant>& variants) {
  CommandPaths paths;
  paths.input("base", options.base).input("variants", options.variantsFile);
  const std::string& dir = options.outputDir;
  paths.output("-o", VariantsPlan::path(dir))
      .output("-o", dir + "/variants.csv")
      .output("-o", dir + "/index.html");
  for (const Variant& variant : variants)
    paths.output("-o", dir + "/" + variant.name + ".png")
        .output("-o", VariantManifest::path(dir, variant.name));
  paths.check();
}

OutputDirectory outputDirectory(const VariantsOptions& options) {
  return {"-o", options.outputDir, "the sweep's pictures, manifests and reports"};
}

OutputDirectory slurmDirectory(const VariantsOptions& options) {
  return {"--slurm", options.slurmDir, "the job scripts"};
}

int writeSlurmScripts(const VariantsOptions& options, const VariantsPlan& plan) {
  namespace fs = std::filesystem;
  const int variants = int(plan.variants.size());
  if (options.shards < 0)
    throw InputError("--shards " + std::to_string(options.shards) +
                     ": error: expected a whole number of at least 1");
  if (options.limit < 0)
    throw InputError("--limit " + std::to_string(options.limit) +
                     ": error: expected a whole number of at least 1 (0: no limit)");
  // More tasks than variants would leave some with nothing to render.
  const int shards = std::min(options.shards > 0 ? options.shards : 8, variants);
  SlurmScript script;
  script.outputDir = fs::absolute(options.outputDir).lexically_normal().string();
  script.shardCommand = partCommand(options, fs::absolute(options.base).string(),
                                    fs::absolute(options.variantsFile).string(), script.outputDir);
  script.shardCommand.push_back("--jobs");
  script.shardCommand.push_back(std::to_string(options.jobs));
  script.mergeExecutable = currentExecutable();
  script.shards = shards;
  script.limit = options.limit;
  script.cpusPerTask = options.jobs;
  // Absolute, as docs/VARIANTS.md says: submit.sh names the job scripts, and is run from
  // wherever the user stands when submitting.
  const std::string scriptDir = fs::absolute(options.slurmDir).lexically_normal().string();
  slurmDirectory(options).create();
  OutputDirectory{"-o", script.outputDir + "/manifests", "the sweep's pictures and manifests"}
      .create();
  // The plan as the tasks will write it (their paths are absolute; the hashes do not depend
  // on paths), so --status counts every variant pending from now on.
  VariantsPlan tasksPlan = plan;
  tasksPlan.base = fs::absolute(options.base).string();
  tasksPlan.variantsFile = fs::absolute(options.variantsFile).string();
  tasksPlan.write(script.outputDir);
  const std::string submit = script.write(scriptDir);
  std::cout << "wrote " << scriptDir << "/variants.sbatch (a job array of " << shards
            << " tasks for " << variants << " variants) and " << scriptDir << "/merge.sbatch\n"
            << "submit both with:  sh " << submit << "\n"
            << "progress:          "
            << shellCommand({currentExecutable(), "variants-merge", "--status", script.outputDir})
            << "\n";
  return 0;
}

// A count the command line gives, which must be a whole number of at least 1.
void checkCount(const char* option, int value) {
  if (value < 1)
    throw InputError(std::string(option) + " " + std::to_string(value) +
                     ": error: expected a whole number of at least 1");
}

// What no variant could render with, refused before the variants file is read: every
// variant's render checks its own size (memory for its shadow method, the GL limits); this
// refuses at once what none could render with --jobs at a time.
void checkRenderOptions(const VariantsOptions& options) {
  const ImageSize size = ImageSize::parse(options.size, "--size");
  checkCount("--frames", options.frames);
  checkCount("--jobs", options.jobs);
  MemoryBudget::check(size, {kFrameBytesPerPixel, kFrameFixedBytes},
                      "a render of the plainest variant", options.jobs, MemoryBudget::available());
  outputDirectory(options).check();
  if (!options.slurmDir.empty()) slurmDirectory(options).check();
}

// The options that split a sweep into parts go together: --shards and --limit shape the
// Slurm array, whose scripts cover the whole sweep and choose a part per array task.
void checkPartOptions(const VariantsOptions& options) {
  if (options.slurmDir.empty() && (options.shards != 0 || options.limit != 0))
    throw InputError(std::string(options.shards != 0 ? "--shards" : "--limit") +
                     ": error: only for --slurm DIR (the array's tasks); a run of one part "
                     "takes --shard K/N");
  if (!options.slurmDir.empty() &&
      (!options.shard.empty() || !options.only.empty() || options.list))
    throw InputError(
        "--slurm: error: writes the scripts of the whole sweep; it cannot be "
        "combined with --shard, --only or --list");
}

// One line a variant: its name, a tab, and the command that renders it alone, for GNU
// parallel or any queue (docs/VARIANTS.md).
void listParts(const VariantsOptions& options, const VariantsPlan& plan,
               const std::vector<std::size_t>& selected) {
  for (std::size_t i : selected) {
    std::vector<std::string> command =
        partCommand(options, options.base, options.variantsFile, options.outputDir);
    command.push_back("--only");
    command.push_back(plan.variants[i].name);
    std::cout << plan.variants[i].name << '\t' << shellCommand(command) << '\n';
  }
}

// The selected variants left to render: one whose manifest is current and whose picture
// exists was rendered by an earlier run (or another shard); it is kept, not rendered again.
std::vector<std::size_t> variantsToRender(const VariantsOptions& options, const VariantsPlan& plan,
                                          const std::vector<std::size_t>& selected) {
  const SweepState before =
      SweepState::collect(plan, options.outputDir, SweepState::BrokenManifest::RenderAgain);
  std::vector<std::size_t> todo;
  for (std::size_t i : selected)
    if (!before.outcomes[i].ok()) todo.push_back(i);
  return todo;
}

// The whole sweep ran here: the reports, as variants-merge would write them.
int reportWholeSweep(const VariantsOptions& options, const VariantsPlan& plan,
                     const std::string& keptText) {
  const SweepState state = SweepState::collect(plan, options.outputDir);
  reportSweep(plan, state, options.outputDir);
  std::cout << "rendered " << state.done << " of " << plan.variants.size() << " variants to "
            << options.outputDir << " (variants.csv, index.html" << keptText << ")\n";
  return state.exitStatus();
}

// A part of a sweep: its errors now, the reports from variants-merge once all parts ran.
int reportPart(const VariantsOptions& options, const VariantsPlan& plan,
               const std::vector<std::size_t>& selected, const SweepRun& run,
               const std::string& keptText) {
  for (std::size_t i : run.todo()) {
    const std::optional<VariantManifest> manifest =
        VariantManifest::read(options.outputDir, plan.variants[i].name);
    if (manifest && !manifest->ok()) std::cerr << manifest->error << '\n';
  }
  const std::string part =
      options.shard.empty() ? "the variants --only names" : "shard " + options.shard;
  const std::string merge =
      "; `ivshadow variants-merge " + options.outputDir + "` writes the reports\n";
  if (selected.empty()) {
    // More shards than variants: this one was given none.
    std::cout << part << " holds none of the sweep's " << plan.variants.size()
              << " variants; nothing to render" << merge;
  } else if (run.todo().empty()) {
    // "rendered 0 of 0" would read as a failure; the part is done, by this or another run.
    std::cout << part << ": nothing left to render; all " << selected.size()
              << " of its variants were already rendered to " << options.outputDir << merge;
  } else {
    std::cout << "rendered " << run.rendered() << " of " << run.todo().size() << " variants"
              << (options.shard.empty() ? std::string() : " of shard " + options.shard) << " to "
              << options.outputDir << keptText << merge;
  }
  return run.exitStatus();
}

}  // namespace

int runVariants(const VariantsOptions& options) {
  // Ctrl-C (or SIGTERM) stops starting renders, interrupts the running ones, cleans up their
  // scratch files and writes no report: exit 128 + the signal, the variants finished before it
  // kept.
  const InterruptGuard guard;
  const std::atomic<bool>& interrupted = InterruptGuard::flag();
  return withExitStatus([&] {
    checkRenderOptions(options);
    std::vector<Variant> parsed = readVariantsFile(options.variantsFile);
    checkOutputPaths(options, parsed);
    const std::vector<std::size_t> selected = selectVariants(options, parsed);
    init();
    loadScene(options.base);  // a broken base scene is one error, not one per variant
    const VariantsPlan plan = VariantsPlan::make(options.base, options.variantsFile, options.size,
                                                 options.frames, std::move(parsed));
    checkPartOptions(options);
    if (!options.slurmDir.empty()) return writeSlurmScripts(options, plan);
    if (options.list) {
      listParts(options, plan, selected);
      return 0;
    }
    outputDirectory(options).create();
    OutputDirectory{"-o", options.outputDir + "/manifests", "the sweep's manifests"}.create();
    plan.write(options.outputDir);

    SweepRun run(options, plan, variantsToRender(options, plan, selected), interrupted);
    run.renderAll();
    if (interrupted) {
      std::cerr << "ivshadow: interrupted: " << run.rendered() << " of " << run.todo().size()
                << " variants rendered to " << options.outputDir << "; no report written\n";
      return InterruptGuard::exitStatus();
    }
    const std::size_t kept = selected.size() - run.todo().size();
    const std::string keptText =
        kept > 0 ? ", " + std::to_string(kept) + " kept from an earlier run" : std::string();
    if (options.shard.empty() && options.only.empty())
      return reportWholeSweep(options, plan, keptText);
    return reportPart(options, plan, selected, run, keptText);
  });
}

}  // namespace ivshadow
