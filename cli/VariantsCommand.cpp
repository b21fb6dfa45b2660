#include "cli/VariantsCommand.h"

#include "cli/ChildProcesses.h"
#include "cli/ExitStatus.h"
#include "cli/InterruptGuard.h"
#include "cli/OutputDirectory.h"
#include "cli/ProgressBar.h"
#include "cli/RenderMemory.h"
#include "cli/SlurmScript.h"
#include "cli/VariantManifest.h"
#include "cli/VariantRenders.h"
#include "cli/VariantShard.h"
#include "cli/VariantsMerge.h"
#include "cli/VariantsPlan.h"
#include "image/AtomicFile.h"
#include "image/CommandPaths.h"
#include "image/ImageSize.h"
#include "image/MemoryBudget.h"
#include "ivshadow/IvShadowInit.h"
#include "scene/InputError.h"
#include "scene/SceneLoader.h"
#include "scene/VariantsFile.h"

#include <Inventor/nodes/SoSeparator.h>
#include <unistd.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <set>

namespace ivshadow {
namespace {

std::string hostName() {
  char name[256] = {};
  gethostname(name, sizeof name - 1);
  return name;
}

std::string readFirstLine(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  return line;
}

// The child names the --set that failed; the variants file line of that assignment is where
// the user must look.
int lineOfFailure(const Variant& variant, const std::string& error) {
  for (const Variant::Assignment& assignment : variant.assignments)
    if (error.find(assignment.text) != std::string::npos) return assignment.line;
  return variant.line;
}

// Files a render killed while writing leaves: the temporaries (AtomicFile's ".FILE.tmpPID")
// of its picture and of its statistics scratch file, in the output directory.
void removeTemporaries(const std::string& dir, const std::string& name) {
  std::error_code ec;
  const std::string prefixes[] = {"." + name + ".png.tmp", ".." + name + ".stats.json.tmp"};
  for (const auto& entry : std::filesystem::directory_iterator(dir, ec))
    for (const std::string& prefix : prefixes)
      if (entry.path().filename().string().rfind(prefix, 0) == 0)
        std::filesystem::remove(entry.path(), ec);
}

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

}  // namespace

int runVariants(const VariantsOptions& options) {
  // Ctrl-C (or SIGTERM) stops starting renders, interrupts the running ones, cleans up their
  // scratch files and writes no report: exit 128 + the signal, the variants finished before it
  // kept.
  const InterruptGuard guard;
  const std::atomic<bool>& interrupted = InterruptGuard::flag();
  return withExitStatus([&] {
    const ImageSize size = ImageSize::parse(options.size, "--size");
    if (options.frames < 1)
      throw InputError("--frames " + std::to_string(options.frames) +
                       ": error: expected a whole number of at least 1");
    if (options.jobs < 1)
      throw InputError("--jobs " + std::to_string(options.jobs) +
                       ": error: expected a whole number of at least 1");
    // Every variant's render checks its own size (memory for its shadow method, the GL
    // limits); this refuses at once what no variant could render with --jobs at a time.
    MemoryBudget::check(size, {kFrameBytesPerPixel, kFrameFixedBytes},
                        "a render of the plainest variant", options.jobs,
                        MemoryBudget::available());
    outputDirectory(options).check();
    if (!options.slurmDir.empty()) slurmDirectory(options).check();
    std::vector<Variant> parsed = readVariantsFile(options.variantsFile);
    checkOutputPaths(options, parsed);
    const std::vector<std::size_t> selected = selectVariants(options, parsed);
    init();
    loadScene(options.base);  // a broken base scene is one error, not one per variant
    const VariantsPlan plan = VariantsPlan::make(options.base, options.variantsFile, options.size,
                                                 options.frames, std::move(parsed));
    const std::vector<Variant>& variants = plan.variants;
    if (options.slurmDir.empty() && (options.shards != 0 || options.limit != 0))
      throw InputError(std::string(options.shards != 0 ? "--shards" : "--limit") +
                       ": error: only for --slurm DIR (the array's tasks); a run of one part "
                       "takes --shard K/N");
    if (!options.slurmDir.empty()) {
      // The scripts cover the whole sweep; a part of it is chosen per array task.
      if (!options.shard.empty() || !options.only.empty() || options.list)
        throw InputError(
            "--slurm: error: writes the scripts of the whole sweep; it cannot be "
            "combined with --shard, --only or --list");
      return writeSlurmScripts(options, plan);
    }
    if (options.list) {
      // One line a variant: its name, a tab, and the command that renders it alone, for GNU
      // parallel or any queue (docs/VARIANTS.md).
      for (std::size_t i : selected) {
        std::vector<std::string> command =
            partCommand(options, options.base, options.variantsFile, options.outputDir);
        command.push_back("--only");
        command.push_back(variants[i].name);
        std::cout << variants[i].name << '\t' << shellCommand(command) << '\n';
      }
      return 0;
    }
    outputDirectory(options).create();
    OutputDirectory{"-o", options.outputDir + "/manifests", "the sweep's manifests"}.create();
    std::error_code made;
    plan.write(options.outputDir);

    // A variant whose manifest is current and whose picture exists was rendered by an
    // earlier run (or another shard); it is kept, not rendered again.
    const SweepState before =
        SweepState::collect(plan, options.outputDir, SweepState::BrokenManifest::RenderAgain);
    std::vector<std::size_t> todo;
    for (std::size_t i : selected)
      if (!before.outcomes[i].ok()) todo.push_back(i);
    const int kept = int(selected.size() - todo.size());

    const std::string host = hostName();
    ProgressBar bar;
    const std::unique_ptr<VariantRenders> renders = VariantRenders::create(options.jobs);
    std::vector<std::chrono::steady_clock::time_point> started(variants.size());
    std::size_t next = 0;
    int finished = 0, rendered = 0, failed = 0, badInput = 0;
    const int total = int(todo.size());
    auto scratch = [&](std::size_t i, const char* what) {
      return options.outputDir + "/." + variants[i].name + what;
    };
    bool stopping = false;
    std::set<std::string> saidIdle;
    // Keeps every worker busy: called again as soon as a render ends, so that the next
    // variant renders while this process files the one that ended.
    const auto startRenders = [&] {
      while (next < todo.size() && !renders->full() && !interrupted) {
        const std::size_t i = todo[next];
        RenderOptions render;
        render.scene = options.base;
        render.output = options.outputDir + "/" + variants[i].name + ".png";
        render.size = options.size;
        render.frames = options.frames;
        render.statsPath = scratch(i, ".stats.json");
        for (const Variant::Assignment& assignment : variants[i].assignments)
          render.assignments.push_back(assignment.text);
        started[i] = std::chrono::steady_clock::now();
        renders->start(int(i), render, scratch(i, ".log"));
        ++next;
      }
    };
    while ((next < todo.size() && !interrupted) || !renders->empty()) {
      if (interrupted && !stopping) {
        // The terminal sent Ctrl-C to the renders too; a signal sent to this process alone
        // reaches them here.
        stopping = true;
        renders->signalAll(SIGINT);
      }
      startRenders();
      if (renders->empty()) continue;  // interrupted before any render started
      const std::optional<VariantRenders::Finished> ended = renders->waitAny();
      if (!ended) continue;  // a signal: the loop sees to it
      const VariantRenders::Finished& done = *ended;
      const std::size_t i = std::size_t(done.id);
      startRenders();
      if (interrupted && done.exitCode != 0) {
        // Interrupted, not failed: no manifest, so a rerun renders it.
        std::filesystem::remove(scratch(i, ".stats.json"), made);
        std::filesystem::remove(scratch(i, ".log"), made);
        removeTemporaries(options.outputDir, variants[i].name);
        continue;
      }
      VariantManifest outcome;
      outcome.variant = variants[i].name;
      for (const Variant::Assignment& assignment : variants[i].assignments)
        outcome.assignments.push_back(assignment.text);
      outcome.size = options.size;
      outcome.frames = options.frames;
      outcome.hash = plan.hashes[i];
      outcome.host = host;
      outcome.seconds =
          std::chrono::duration<double>(std::chrono::steady_clock::now() - started[i]).count();
      outcome.exitCode = done.exitCode;
      if (done.exitCode == 0) {
        std::ifstream in(scratch(i, ".stats.json"));
        outcome.stats = nlohmann::json::parse(in, nullptr, false);
        // A setting that did nothing on the path this machine renders by: said once here for
        // the sweep, and kept with the variant for its report.
        if (outcome.stats.is_object()) {
          std::ifstream log(scratch(i, ".log"));
          nlohmann::json idle = nlohmann::json::array();
          for (std::string line; std::getline(log, line);) {
            const std::size_t at = line.find("): ");
            if (line.find(" does nothing: ") == std::string::npos) continue;
            const std::string what = at == std::string::npos ? line : line.substr(at + 3);
            idle.push_back(what);
            if (saidIdle.insert(what).second)
              std::cerr << "ivshadow: warning: variant " << variants[i].name << ": " << what
                        << '\n';
          }
          if (!idle.empty()) outcome.stats["idle_settings"] = idle;
        }
      } else {
        const std::string message = readFirstLine(scratch(i, ".log"));
        const char* fallback =
            done.exitCode == -1 ? "the render was killed by a signal" : "the render failed";
        outcome.error = options.variantsFile + ":" +
                        std::to_string(lineOfFailure(variants[i], message)) + ": error: variant " +
                        variants[i].name + ": " + (message.empty() ? fallback : message);
      }
      outcome.write(options.outputDir);
      std::filesystem::remove(scratch(i, ".stats.json"), made);
      std::filesystem::remove(scratch(i, ".log"), made);
      // Also after a retried success: a worker killed while it wrote the variant's files left
      // temporaries named for its own process, which the retry's process did not replace.
      if (done.exitCode != 0 || done.retried)
        removeTemporaries(options.outputDir, variants[i].name);
      if (done.exitCode == 0) {
        ++rendered;
      } else {
        ++failed;
        badInput += done.exitCode == 2 ? 1 : 0;
      }
      bar.update(++finished, total, variants[i].name);
    }
    if (interrupted) {
      std::cerr << "ivshadow: interrupted: " << rendered << " of " << total
                << " variants rendered to " << options.outputDir << "; no report written\n";
      return InterruptGuard::exitStatus();
    }

    const std::string keptText =
        kept > 0 ? ", " + std::to_string(kept) + " kept from an earlier run" : std::string();
    if (options.shard.empty() && options.only.empty()) {
      // The whole sweep ran here: the reports, as variants-merge would write them.
      const SweepState state = SweepState::collect(plan, options.outputDir);
      reportSweep(plan, state, options.outputDir);
      std::cout << "rendered " << state.done << " of " << variants.size() << " variants to "
                << options.outputDir << " (variants.csv, index.html" << keptText << ")\n";
      return state.exitStatus();
    }
    // A part of a sweep: its errors now, the reports from variants-merge once all parts ran.
    for (std::size_t i : todo) {
      const std::optional<VariantManifest> manifest =
          VariantManifest::read(options.outputDir, variants[i].name);
      if (manifest && !manifest->ok()) std::cerr << manifest->error << '\n';
    }
    const std::string part =
        options.shard.empty() ? "the variants --only names" : "shard " + options.shard;
    const std::string merge =
        "; `ivshadow variants-merge " + options.outputDir + "` writes the reports\n";
    if (selected.empty()) {
      // More shards than variants: this one was given none.
      std::cout << part << " holds none of the sweep's " << variants.size()
                << " variants; nothing to render" << merge;
    } else if (todo.empty()) {
      // "rendered 0 of 0" would read as a failure; the part is done, by this or another run.
      std::cout << part << ": nothing left to render; all " << selected.size()
                << " of its variants were already rendered to " << options.outputDir << merge;
    } else {
      std::cout << "rendered " << rendered << " of " << total << " variants"
                << (options.shard.empty() ? std::string() : " of shard " + options.shard) << " to "
                << options.outputDir << keptText << merge;
    }
    if (failed == 0) return 0;
    return badInput == failed ? 2 : 1;
  });
}

}  // namespace ivshadow
