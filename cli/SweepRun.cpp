#include "cli/SweepRun.h"

#include <unistd.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <iostream>

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

}  // namespace

SweepRun::SweepRun(const VariantsOptions& options, const VariantsPlan& plan,
                   std::vector<std::size_t> todo, const std::atomic<bool>& interrupted)
    : options_(options),
      plan_(plan),
      variants_(plan.variants),
      todo_(std::move(todo)),
      interrupted_(interrupted),
      host_(hostName()),
      renders_(VariantRenders::create(options.jobs)),
      started_(plan.variants.size()) {}

void SweepRun::renderAll() {
  while ((next_ < todo_.size() && !interrupted_) || !renders_->empty()) {
    if (interrupted_ && !stopping_) {
      // The terminal sent Ctrl-C to the renders too; a signal sent to this process alone
      // reaches them here.
      stopping_ = true;
      renders_->signalAll(SIGINT);
    }
    startRenders();
    if (renders_->empty()) continue;  // interrupted before any render started
    const std::optional<VariantRenders::Finished> ended = renders_->waitAny();
    if (!ended) continue;  // a signal: the loop sees to it
    startRenders();
    if (interrupted_ && ended->exitCode != 0)
      discard(std::size_t(ended->id));
    else
      file(*ended);
  }
}

int SweepRun::exitStatus() const {
  if (failed_ == 0) return 0;
  return badInput_ == failed_ ? 2 : 1;
}

void SweepRun::startRenders() {
  while (next_ < todo_.size() && !renders_->full() && !interrupted_) {
    const std::size_t i = todo_[next_];
    RenderOptions render;
    render.scene = options_.base;
    render.output = options_.outputDir + "/" + variants_[i].name + ".png";
    render.size = options_.size;
    render.frames = options_.frames;
    render.statsPath = scratch(i, ".stats.json");
    for (const Variant::Assignment& assignment : variants_[i].assignments)
      render.assignments.push_back(assignment.text);
    started_[i] = std::chrono::steady_clock::now();
    renders_->start(int(i), render, scratch(i, ".log"));
    ++next_;
  }
}

void SweepRun::file(const VariantRenders::Finished& done) {
  const std::size_t i = std::size_t(done.id);
  manifestOf(i, done).write(options_.outputDir);
  removeScratch(i);
  // Also after a retried success: a worker killed while it wrote the variant's files left
  // temporaries named for its own process, which the retry's process did not replace.
  if (done.exitCode != 0 || done.retried) removeTemporaries(options_.outputDir, variants_[i].name);
  if (done.exitCode == 0) {
    ++rendered_;
  } else {
    ++failed_;
    badInput_ += done.exitCode == 2 ? 1 : 0;
  }
  bar_.update(++finished_, int(todo_.size()), variants_[i].name);
}

void SweepRun::discard(std::size_t i) const {
  removeScratch(i);
  removeTemporaries(options_.outputDir, variants_[i].name);
}

VariantManifest SweepRun::manifestOf(std::size_t i, const VariantRenders::Finished& done) {
  const Variant& variant = variants_[i];
  VariantManifest outcome;
  outcome.variant = variant.name;
  for (const Variant::Assignment& assignment : variant.assignments)
    outcome.assignments.push_back(assignment.text);
  outcome.size = options_.size;
  outcome.frames = options_.frames;
  outcome.hash = plan_.hashes[i];
  outcome.host = host_;
  outcome.seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - started_[i]).count();
  outcome.exitCode = done.exitCode;
  if (done.exitCode == 0) {
    std::ifstream in(scratch(i, ".stats.json"));
    outcome.stats = nlohmann::json::parse(in, nullptr, false);
    // Kept with the variant for its report.
    if (outcome.stats.is_object()) {
      const nlohmann::json idle = idleSettings(i);
      if (!idle.empty()) outcome.stats["idle_settings"] = idle;
    }
  } else {
    const std::string message = readFirstLine(scratch(i, ".log"));
    const char* fallback =
        done.exitCode == -1 ? "the render was killed by a signal" : "the render failed";
    outcome.error = options_.variantsFile + ":" + std::to_string(lineOfFailure(variant, message)) +
                    ": error: variant " + variant.name + ": " +
                    (message.empty() ? fallback : message);
  }
  return outcome;
}

// A setting that did nothing on the path this machine renders by: said once here for the
// sweep, not once per variant.
nlohmann::json SweepRun::idleSettings(std::size_t i) {
  std::ifstream log(scratch(i, ".log"));
  nlohmann::json idle = nlohmann::json::array();
  for (std::string line; std::getline(log, line);) {
    const std::size_t at = line.find("): ");
    if (line.find(" does nothing: ") == std::string::npos) continue;
    const std::string what = at == std::string::npos ? line : line.substr(at + 3);
    idle.push_back(what);
    if (saidIdle_.insert(what).second)
      std::cerr << "ivshadow: warning: variant " << variants_[i].name << ": " << what << '\n';
  }
  return idle;
}

std::string SweepRun::scratch(std::size_t i, const char* what) const {
  return options_.outputDir + "/." + variants_[i].name + what;
}

void SweepRun::removeScratch(std::size_t i) const {
  std::error_code ec;
  std::filesystem::remove(scratch(i, ".stats.json"), ec);
  std::filesystem::remove(scratch(i, ".log"), ec);
}

}  // namespace ivshadow
