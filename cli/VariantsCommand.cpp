#include "cli/VariantsCommand.h"

#include "cli/ChildProcesses.h"
#include "cli/ExitStatus.h"
#include "cli/InterruptGuard.h"
#include "cli/ProgressBar.h"
#include "cli/RenderMemory.h"
#include "image/AtomicFile.h"
#include "image/ImageSize.h"
#include "image/MemoryBudget.h"
#include "ivshadow/IvShadowInit.h"
#include "scene/InputError.h"
#include "scene/SceneLoader.h"
#include "scene/VariantsFile.h"

#include <Inventor/nodes/SoSeparator.h>
#include <nlohmann/json.hpp>

#include <atomic>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace ivshadow {
namespace {

struct Outcome {
  bool done = false;
  int exitCode = -1;
  std::string error;  // the variant's error line, with its line in the variants file
  nlohmann::json stats;
};

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

std::string htmlEscape(const std::string& text) {
  std::string out;
  for (char c : text) {
    if (c == '<')
      out += "&lt;";
    else if (c == '>')
      out += "&gt;";
    else if (c == '&')
      out += "&amp;";
    else if (c == '"')
      out += "&quot;";
    else
      out += c;
  }
  return out;
}

std::string csvField(const std::string& text) {
  std::string out = "\"";
  for (char c : text) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

std::string assignmentsText(const Variant& variant) {
  std::string text;
  for (const Variant::Assignment& assignment : variant.assignments)
    text += (text.empty() ? "" : "; ") + assignment.text;
  return text;
}

double number(const nlohmann::json& stats, const char* key, const char* inner = nullptr) {
  const nlohmann::json* value = &stats;
  if (!value->contains(key)) return 0.0;
  value = &(*value)[key];
  if (inner) {
    if (!value->contains(inner)) return 0.0;
    value = &(*value)[inner];
  }
  return value->is_number() ? value->get<double>() : 0.0;
}

// Which shadow methods a render used, from its statistics: a map's build time and memory
// mean nothing for a light whose shadows are traced, and the other way round.
struct Methods {
  bool map = false;
  bool rays = false;
};

Methods methodsOf(const nlohmann::json& stats) {
  Methods methods;
  if (!stats.is_object() || !stats.contains("dsm_layers_used")) return methods;
  for (const auto& light : stats["dsm_layers_used"]) {
    const std::string method = light.value("method", std::string());
    methods.map = methods.map || method == "MAP";
    methods.rays = methods.rays || method == "RAYS";
  }
  return methods;
}

// "Lamp:0/2/2/0/0/5" per light that has a map, from the render's statistics.
std::string layersText(const nlohmann::json& stats) {
  std::string text;
  if (!stats.is_object() || !stats.contains("dsm_layers_used")) return text;
  for (const auto& light : stats["dsm_layers_used"]) {
    if (light.value("method", std::string()) != "MAP") continue;
    text += (text.empty() ? "" : " ") + light.value("light", std::string("light")) + ":";
    bool first = true;
    for (int used : light["faces"]) {
      text += (first ? "" : "/") + std::to_string(used);
      first = false;
    }
  }
  return text;
}

std::string shadowMethod(const nlohmann::json& stats) {
  if (!stats.is_object() || !stats.contains("passes")) return {};
  return stats["passes"].value("shadow_method", std::string());
}

// A CSV number, or an empty field when the column does not apply to this render.
std::string field(bool applies, double value) {
  if (!applies) return {};
  std::ostringstream out;
  out << value;
  return out.str();
}

std::string csvLine(const Variant& variant, const Outcome& outcome, const std::string& image) {
  const bool ok = outcome.exitCode == 0;
  const nlohmann::json& stats = outcome.stats;
  const Methods used = ok ? methodsOf(stats) : Methods{};
  std::ostringstream csv;
  csv << csvField(variant.name) << ',' << csvField(assignmentsText(variant)) << ','
      << (ok ? "ok" : "failed") << ',' << shadowMethod(stats) << ','
      << field(ok, number(stats, "frame_ms_median")) << ','
      << field(used.map, number(stats, "passes", "dsm_build_ms")) << ','
      << field(used.rays, number(stats, "passes", "rays_ms")) << ','
      << field(used.rays, number(stats, "passes", "bvh_build_ms")) << ','
      << field(ok, number(stats, "passes", "peel_ms")) << ','
      << field(used.map, number(stats, "dsm_bytes")) << ','
      << field(used.rays, number(stats, "bvh_bytes")) << ',' << csvField(layersText(stats)) << ','
      << (ok ? csvField(image) : "\"\"") << '\n';
  return csv.str();
}

// "12.0 ms a frame, map built in 2.2 ms, 40 KiB, rays traced in 31.0 ms, BVH 96 KiB": the
// figures of the methods the render used.
std::string captionFigures(const nlohmann::json& stats) {
  const Methods used = methodsOf(stats);
  std::ostringstream out;
  out << std::fixed << std::setprecision(1) << number(stats, "frame_ms_median") << " ms a frame";
  if (used.map)
    out << ", map built in " << number(stats, "passes", "dsm_build_ms") << " ms, "
        << std::uint64_t(number(stats, "dsm_bytes")) / 1024 << " KiB";
  if (used.rays)
    out << ", rays traced in " << number(stats, "passes", "rays_ms") << " ms, BVH "
        << std::uint64_t(number(stats, "bvh_bytes")) / 1024 << " KiB";
  return out.str();
}

void writeReports(const VariantsOptions& options, const std::vector<Variant>& variants,
                  const std::vector<Outcome>& outcomes) {
  std::ostringstream csv;
  // Columns of a method the variant did not use (a map's for traced lights, the rays' for
  // mapped ones) are left empty rather than 0, which would read as "free".
  csv << "variant,assignments,status,shadow_method,frame_ms_median,dsm_build_ms,rays_ms,"
         "bvh_build_ms,peel_ms,dsm_bytes,bvh_bytes,dsm_layers_used,image\n";
  std::ostringstream html;
  html << "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>Variants of "
       << htmlEscape(options.base) << "</title>\n<style>body{font-family:sans-serif}"
       << "figure{display:inline-block;margin:8px;width:260px;vertical-align:top}"
       << "img{width:256px;border:1px solid #999}figcaption{font-size:12px}"
       << ".failed{color:#a00}</style></head><body>\n<h1>Variants of " << htmlEscape(options.base)
       << "</h1>\n";
  for (std::size_t i = 0; i < variants.size(); ++i) {
    const Variant& variant = variants[i];
    const Outcome& outcome = outcomes[i];
    const bool ok = outcome.exitCode == 0;
    const std::string image = variant.name + ".png";
    csv << csvLine(variant, outcome, image);
    html << "<figure id=\"" << htmlEscape(variant.name) << "\">";
    if (ok)
      html << "<a href=\"" << htmlEscape(image) << "\"><img src=\"" << htmlEscape(image)
           << "\" alt=\"" << htmlEscape(variant.name) << "\"></a>";
    html << "<figcaption><b>" << htmlEscape(variant.name) << "</b><br>"
         << htmlEscape(assignmentsText(variant)) << "<br>";
    if (ok)
      html << htmlEscape(captionFigures(outcome.stats));
    else
      html << "<span class=\"failed\">" << htmlEscape(outcome.error) << "</span>";
    html << "</figcaption></figure>\n";
  }
  html << "</body></html>\n";
  writeTextFileAtomically(options.outputDir + "/variants.csv", csv.str());
  writeTextFileAtomically(options.outputDir + "/index.html", html.str());
}

// Files a render killed while writing leaves: its output's temporary (AtomicFile's
// ".NAME.png.tmpPID") in the output directory.
void removeTemporaries(const std::string& dir, const std::string& name) {
  std::error_code ec;
  const std::string prefix = "." + name + ".png.tmp";
  for (const auto& entry : std::filesystem::directory_iterator(dir, ec))
    if (entry.path().filename().string().rfind(prefix, 0) == 0)
      std::filesystem::remove(entry.path(), ec);
}

}  // namespace

int runVariants(const VariantsOptions& options) {
  // Ctrl-C (or SIGTERM) stops starting renders, interrupts the running ones, cleans up their
  // scratch files and writes no report: exit 130, the variants finished before it kept.
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
    const std::vector<Variant> variants = readVariantsFile(options.variantsFile);
    init();
    loadScene(options.base);  // a broken base scene is one error, not one per variant
    std::error_code made;
    std::filesystem::create_directories(options.outputDir, made);
    if (made || !std::filesystem::is_directory(options.outputDir))
      throw InputError(options.outputDir + ": error: cannot create the output directory");

    const std::string self = currentExecutable();
    ProgressBar bar;
    std::vector<Outcome> outcomes(variants.size());
    ChildProcesses children(options.jobs);
    std::size_t next = 0;
    int finished = 0, rendered = 0;
    const int total = int(variants.size());
    auto scratch = [&](std::size_t i, const char* what) {
      return options.outputDir + "/." + variants[i].name + what;
    };
    bool stopping = false;
    while ((next < variants.size() && !interrupted) || !children.empty()) {
      if (interrupted && !stopping) {
        // The terminal sent Ctrl-C to the renders too; a signal sent to this process alone
        // reaches them here.
        stopping = true;
        children.signalAll(SIGINT);
      }
      while (next < variants.size() && !children.full() && !interrupted) {
        std::vector<std::string> command = {self,
                                            "render",
                                            options.base,
                                            "-o",
                                            options.outputDir + "/" + variants[next].name + ".png",
                                            "--size",
                                            options.size,
                                            "--frames",
                                            std::to_string(options.frames),
                                            "--stats",
                                            scratch(next, ".stats.json")};
        for (const Variant::Assignment& assignment : variants[next].assignments) {
          command.push_back("--set");
          command.push_back(assignment.text);
        }
        children.start(int(next), command, scratch(next, ".log"));
        ++next;
      }
      const ChildProcesses::Finished done = children.waitAny();
      const std::size_t i = std::size_t(done.id);
      Outcome& outcome = outcomes[i];
      outcome.done = true;
      outcome.exitCode = done.exitCode;
      if (done.exitCode == 0) {
        std::ifstream in(scratch(i, ".stats.json"));
        outcome.stats = nlohmann::json::parse(in, nullptr, false);
      } else {
        const std::string message = readFirstLine(scratch(i, ".log"));
        outcome.error = options.variantsFile + ":" +
                        std::to_string(lineOfFailure(variants[i], message)) + ": error: variant " +
                        variants[i].name + ": " + (message.empty() ? "the render failed" : message);
      }
      std::filesystem::remove(scratch(i, ".stats.json"), made);
      std::filesystem::remove(scratch(i, ".log"), made);
      if (done.exitCode != 0) removeTemporaries(options.outputDir, variants[i].name);
      if (done.exitCode == 0) ++rendered;
      bar.update(++finished, total, variants[i].name);
    }
    if (interrupted) {
      std::cerr << "ivshadow: interrupted: " << rendered << " of " << total
                << " variants rendered to " << options.outputDir << "; no report written\n";
      return 130;
    }

    writeReports(options, variants, outcomes);
    int failed = 0, badInput = 0;
    for (const Outcome& outcome : outcomes) {
      if (outcome.exitCode == 0) continue;
      ++failed;
      badInput += outcome.exitCode == 2 ? 1 : 0;
      std::cerr << outcome.error << '\n';
    }
    std::cout << "rendered " << total - failed << " of " << total << " variants to "
              << options.outputDir << " (variants.csv, index.html)\n";
    if (failed == 0) return 0;
    return badInput == failed ? 2 : 1;
  });
}

}  // namespace ivshadow
