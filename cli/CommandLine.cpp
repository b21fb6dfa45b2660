#include "cli/CommandLine.h"

#include "cli/CompareCommand.h"
#include "cli/ReferenceCommand.h"
#include "cli/RenderCommand.h"
#include "cli/TradeCommand.h"
#include "cli/VariantsCommand.h"
#include "cli/VariantsMerge.h"
#include "cli/VariantsWorker.h"
#include "cli/ViewerProcess.h"
#include "ivshadow/IvShadowInit.h"

#include <algorithm>
#include <cctype>
#include <iostream>
#include <vector>

namespace ivshadow {
namespace {
const char* kExitStatus =
    R"(Exit status: 0 success, 2 bad input (file, field, option, size), 3 no GL context
or display, 1 any other failure. No output file is written unless the command succeeds.)";

// Each command's --help shows its own examples; the top level shows one per command.
std::string footer(const std::string& examples) {
  return "Examples:\n" + examples + "\n" + kExitStatus;
}

const char* kOverview = R"(  ivshadow render iv_scenes/glass_over_floor.iv -o glass.png
  ivshadow variants iv_scenes/coloured_shadows.iv iv_scenes/coloured_shadows.variants -o out/v
  ivshadow reference scene.iv -o exact.png --size 640x480
  ivshadow trade iv_scenes/coloured_shadows.iv -o out/trade --layers 1,4 --filter none
  ivshadow compare reference.png render.png --diff diff.png
  ivshadow view iv_scenes/glass_over_floor.iv
Run "ivshadow COMMAND --help" for a command's options and examples.)";

const char* kRenderExamples = R"(  ivshadow render iv_scenes/glass_over_floor.iv -o glass.png
  ivshadow render scene.iv -o glass.jpg --size 1920x1080
  ivshadow render scene.iv -o big.png --size 1920x1080 --frames 20 --stats stats.json
  ivshadow render scene.iv -o red.png --set Glass.diffuseColor="1 0 0" --set Lamp.intensity=0.5
  ivshadow render scene.iv -o coin.png --transparency SORTED_OBJECT_BLEND
The image format follows the file name: .png, or .jpg / .jpeg.)";

const char* kVariantsExamples =
    R"(  ivshadow variants iv_scenes/coloured_shadows.iv iv_scenes/coloured_shadows.variants -o out/v
  ivshadow variants scene.iv grid.variants -o out/grid --size 320x240 --frames 1 --jobs 2
A line "sweep grid Lamp.maxLayers = 1 .. 5 step 1 * Lamp.resolution = 128 | 256 | 512"
renders the 5 x 3 crossed grid (docs/VARIANTS.md).
On a cluster or with GNU parallel (docs/VARIANTS.md, "On a cluster"):
  ivshadow variants scene.iv grid.variants -o out/grid --shard 0/4   # the first of 4 parts
  ivshadow variants scene.iv grid.variants -o out/grid --list | cut -f2 | parallel -j2
  ivshadow variants scene.iv grid.variants -o /shared/grid --slurm /shared/jobs --shards 4
  ivshadow variants-merge out/grid)";

const char* kMergeExamples = R"(  ivshadow variants-merge out/grid
  ivshadow variants-merge --status out/grid)";

const char* kReferenceExamples = R"(  ivshadow reference iv_scenes/coloured_shadows.iv -o exact.png
  ivshadow reference scene.iv -o exact.png --size 640x480 --pfm exact.pfm
  ivshadow reference scene.iv -o exact.jpg --set Lamp.location="0 0 3" --threads 2
  ivshadow reference iv_scenes/bounce_wall.iv -o bounce.png --bounce 256)";

const char* kTradeExamples = R"(  ivshadow trade iv_scenes/coloured_shadows.iv -o out/trade
  ivshadow trade scene.iv -o out/trade --layers 1,4 --filter none --method map
  ivshadow trade scene.iv -o out/trade --resolution 256,512 --precision half --size 160x120)";

const char* kCompareExamples = R"(  ivshadow compare reference.png render.png
  ivshadow compare reference.png render.png --diff diff.png --scale 16 --json metrics.json)";

const char* kViewExamples = R"(  ivshadow view iv_scenes/glass_over_floor.iv
  ivshadow view scene.iv --screenshot shot.png --size 640x480)";

// CLI11 says only "A subcommand is required" for a mistyped command; this names it and the
// valid ones. Empty when the first argument is an option or a known command.
std::string unknownCommand(int argc, char** argv, const CLI::App& app) {
  const auto all = [](const CLI::App*) { return true; };
  std::string valid;
  for (const CLI::App* command : app.get_subcommands(all))
    if (!command->get_group().empty())  // the hidden variants-worker is no user's command
      valid += (valid.empty() ? "" : ", ") + command->get_name();
  if (argc < 2) return "ivshadow: error: expected a command: " + valid;
  const std::string first = argv[1];
  if (first.empty() || first[0] == '-') return {};
  for (const CLI::App* command : app.get_subcommands(all))
    if (command->get_name() == first) return {};
  return "ivshadow: error: unknown command '" + first + "'; expected one of " + valid +
         " (ivshadow --help lists them)";
}

std::size_t editDistance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

// The option of `command` the user most likely meant by `name` (CLI11 2.1 suggests none): one
// that `name` begins (--out: --output) or within two typing mistakes of it (--sise: --size).
std::string closestOption(const CLI::App& command, const std::string& name) {
  std::string best;
  std::size_t bestScore = 3;
  for (const CLI::Option* option : command.get_options()) {
    std::vector<std::string> spellings;
    for (const std::string& l : option->get_lnames()) spellings.push_back("--" + l);
    for (const std::string& s : option->get_snames()) spellings.push_back("-" + s);
    for (const std::string& spelling : spellings) {
      const bool begins = name.size() >= 3 && spelling.rfind(name, 0) == 0;
      const std::size_t score = begins ? 1 : editDistance(name, spelling);
      if (score < bestScore && score * 3 <= spelling.size()) {
        best = spelling;
        bestScore = score;
      }
    }
  }
  return best;
}

// CLI11 checks required options before it reports unknown ones: `trade S.iv --out D` said only
// "--output is required". The unknown option is what the user must correct, so it is named
// first, with the option it most likely stands for. Empty when nothing unknown was given.
std::string unknownOption(const CLI::App& app) {
  const CLI::App* command = &app;
  for (const CLI::App* sub : app.get_subcommands()) command = sub;
  for (const std::string& word : app.remaining(true)) {
    // Only options: a stray value, or a negative number, is CLI11's to report.
    if (word.size() < 2 || word[0] != '-' || word == "--" ||
        std::isdigit(static_cast<unsigned char>(word[1])) || word[1] == '.')
      continue;
    const std::string name = word.substr(0, word.find('='));
    const std::string close = closestOption(*command, name);
    const std::string commandName =
        command == &app ? app.get_name() : app.get_name() + " " + command->get_name();
    return app.get_name() + ": error: unknown option '" + name + "'" +
           (close.empty() ? std::string() : "; did you mean " + close + "?") + "\nRun \"" +
           commandName + " --help\" for the options.\n";
  }
  return {};
}

}  // namespace

CommandLine::CommandLine()
    : app_{"ivshadow: render Open Inventor scenes with transparent, coloured shadows", "ivshadow"} {
  app_.footer(footer(kOverview));
  app_.set_version_flag("--version", std::string("ivshadow ") + version());
  app_.require_subcommand(1);
  useProjectErrorFormat(app_);

  renderCommand_ = app_.add_subcommand("render", "Render an .iv file to a PNG or JPEG headlessly");
  renderCommand_->footer(footer(kRenderExamples));
  renderCommand_->add_option("scene", render_.scene, "Open Inventor scene file (.iv)")->required();
  renderCommand_->add_option("-o,--output", render_.output, "Image to write: .png, .jpg or .jpeg")
      ->required();
  renderCommand_->add_option("--size", render_.size, "Image size WIDTHxHEIGHT")
      ->capture_default_str();
  renderCommand_->add_option("--frames", render_.frames, "Frames to render and time")
      ->capture_default_str();
  renderCommand_->add_option("--stats", render_.statsPath, "Write timing statistics as JSON");
  renderCommand_
      ->add_option("--set", render_.assignments,
                   "Assign NAME.field=VALUE (Inventor syntax) to DEF-named nodes")
      ->allow_extra_args(false);
  renderCommand_->add_option("--transparency", render_.transparency,
                             "Coin transparency type, e.g. BLEND, SORTED_LAYERS_BLEND");

  variantsCommand_ =
      app_.add_subcommand("variants", "Render scripted variants of a scene (docs/VARIANTS.md)");
  variantsCommand_->footer(footer(kVariantsExamples));
  variantsCommand_->add_option("base", variants_.base, "Open Inventor scene file (.iv)")
      ->required();
  variantsCommand_->add_option("variants", variants_.variantsFile, "Variants file")->required();
  variantsCommand_->add_option("-o,--output", variants_.outputDir, "Directory to write to")
      ->required();
  variantsCommand_->add_option("--size", variants_.size, "Image size WIDTHxHEIGHT")
      ->capture_default_str();
  variantsCommand_->add_option("--frames", variants_.frames, "Frames to render and time")
      ->capture_default_str();
  variantsCommand_->add_option("--jobs,-j", variants_.jobs, "Variants rendered at once")
      ->capture_default_str();
  variantsCommand_->add_option("--shard", variants_.shard,
                               "Render part K of N: the variants whose index is K modulo N");
  variantsCommand_
      ->add_option("--only", variants_.only, "Render only the variant NAME (repeatable)")
      ->allow_extra_args(false);
  variantsCommand_->add_flag("--list", variants_.list,
                             "Print each variant's name, a tab and the command rendering it alone");
  variantsCommand_->add_option(
      "--slurm", variants_.slurmDir,
      "Write Slurm job array and merge scripts to DIR instead of rendering");
  variantsCommand_->add_option("--shards", variants_.shards,
                               "--slurm: array tasks, one shard each (default 8)");
  variantsCommand_->add_option("--limit", variants_.limit,
                               "--slurm: array tasks running at once (default no limit)");

  mergeCommand_ = app_.add_subcommand(
      "variants-merge", "Write variants_.csv and index.html from the manifests of every shard");
  mergeCommand_->footer(footer(kMergeExamples));
  mergeCommand_->add_option("dir", merge_.outputDir, "The sweep's output directory")->required();
  mergeCommand_->add_flag("--status", merge_.statusOnly,
                          "Only print the done, failed and pending counts");

  referenceCommand_ = app_.add_subcommand(
      "reference", "Render the exact picture on the CPU (Embree ray tracing) to compare with");
  referenceCommand_->footer(footer(kReferenceExamples));
  referenceCommand_->add_option("scene", reference_.scene, "Open Inventor scene file (.iv)")
      ->required();
  referenceCommand_
      ->add_option("-o,--output", reference_.output, "Image to write: .png, .jpg or .jpeg")
      ->required();
  referenceCommand_->add_option("--size", reference_.size, "Image size WIDTHxHEIGHT")
      ->capture_default_str();
  referenceCommand_->add_option("--pfm", reference_.pfm,
                                "Also write the unrounded colours as a float PFM");
  referenceCommand_
      ->add_option("--set", reference_.assignments,
                   "Assign NAME.field=VALUE (Inventor syntax) to DEF-named nodes")
      ->allow_extra_args(false);
  bounceOption_ =
      referenceCommand_
          ->add_option("--bounce", reference_.bounce,
                       "Rays per point of the one diffuse bounce of groups with bounce TRUE, "
                       "rounded up to a square (0: no bounce)")
          ->capture_default_str();
  referenceCommand_->add_option("--threads", reference_.threads, "Worker threads (0: every core)")
      ->capture_default_str();

  tradeCommand_ = app_.add_subcommand(
      "trade", "Time every deep shadow setting and measure its error against the reference");
  tradeCommand_->footer(footer(kTradeExamples));
  tradeCommand_->add_option("scene", trade_.scene, "Open Inventor scene file (.iv)")->required();
  tradeCommand_->add_option("-o,--output", trade_.outputDir, "Directory for trade_.csv, trade_.png")
      ->required();
  tradeCommand_->add_option("--size", trade_.size, "Image size WIDTHxHEIGHT")
      ->capture_default_str();
  tradeCommand_->add_option("--resolution", trade_.resolutions, "Cube face sizes, comma-separated")
      ->delimiter(',')
      ->capture_default_str();
  tradeCommand_->add_option("--layers", trade_.layers, "Layer caps, comma-separated")
      ->delimiter(',')
      ->capture_default_str();
  tradeCommand_
      ->add_option("--precision", trade_.precisions, joinedList(kTradePrecisions, "and/or"))
      ->delimiter(',')
      ->capture_default_str();
  tradeCommand_
      ->add_option("--filter", trade_.filters,
                   joinedList(kTradeFilters, "and/or") +
                       " (bilinear: PCF over one texel; pcf: over 3 x 3 texels)")
      ->delimiter(',')
      ->capture_default_str();
  tradeCommand_->add_option("--slices", trade_.slices, "Opacity map slice counts, comma-separated")
      ->delimiter(',')
      ->capture_default_str();
  tradeCommand_
      ->add_option("--method", trade_.methods,
                   joinedList(kTradeMethods, "and/or") + " (tracer: the group traced whole)")
      ->delimiter(',')
      ->capture_default_str();
  tradeCommand_->add_option("--frames", trade_.frames, "Frames timed per setting (median)")
      ->capture_default_str();

  compareCommand_ = app_.add_subcommand(
      "compare", "Measure how far one picture (PNG or JPEG) is from another (the reference)");
  compareCommand_->footer(footer(kCompareExamples));
  compareCommand_->add_option("reference", compare_.reference, "The picture taken as right")
      ->required();
  compareCommand_->add_option("candidate", compare_.candidate, "The picture measured")->required();
  compareCommand_->add_option("--diff", compare_.diffPath,
                              "Write a heat map of the error (.png or .jpg)");
  compareCommand_->add_option("--scale", compare_.scale,
                              "Heat map: error in 8-bit steps shown as white (0: the largest)");
  compareCommand_->add_option("--json", compare_.jsonPath, "Write the metrics as JSON");

  // Started by `variants` (cli/VariantsWorker.h); not for users, so in no help or list.
  workerCommand_ =
      app_.add_subcommand("variants-worker", "Render the variants a sweep sends on stdin")
          ->group("");

  viewCommand_ = app_.add_subcommand("view", "Open an .iv file in the viewer");
  viewCommand_->footer(footer(kViewExamples));
  addViewerOptions(*viewCommand_, view_);
}

std::optional<int> CommandLine::parse(int argc, char** argv) {
  if (const std::string unknown = unknownCommand(argc, argv, app_); !unknown.empty()) {
    std::cerr << unknown << '\n';
    return 2;
  }
  try {
    app_.parse(argc, argv);
    // The command is the first argument that is not an option (ivshadow's own options take no
    // value), so what follows `view` is the viewer's command line.
    if (viewCommand_->parsed()) {
      int first = 1;
      while (first < argc && std::string(argv[first]) != "view") ++first;
      viewArguments_.assign(argv + std::min(first + 1, argc), argv + argc);
    }
  } catch (const CLI::ParseError& error) {
    if (const std::string unknown = unknownOption(app_);
        error.get_exit_code() != 0 && !unknown.empty()) {
      std::cerr << unknown;
      return 2;
    }
    const int status = app_.exit(error);
    return status == 0 ? 0 : 2;
  }
  return std::nullopt;
}

std::string CommandLine::command() const {
  for (const CLI::App* command : app_.get_subcommands())
    if (command->parsed()) return command->get_name();
  return {};
}

int CommandLine::run() {
  if (renderCommand_->parsed()) return runRender(render_);
  if (variantsCommand_->parsed()) return runVariants(variants_);
  if (mergeCommand_->parsed()) return runVariantsMerge(merge_);
  if (workerCommand_->parsed()) return runVariantsWorker();
  if (compareCommand_->parsed()) return runCompare(compare_);
  if (referenceCommand_->parsed()) {
    reference_.bounceGiven = bounceOption_->count() > 0;
    return runReference(reference_);
  }
  if (tradeCommand_->parsed()) return runTrade(trade_);
  return runViewerProcess(viewArguments_);
}

}  // namespace ivshadow
