#include "cli/CompareCommand.h"
#include "cli/ReferenceCommand.h"
#include "cli/RenderCommand.h"
#include "cli/TradeCommand.h"
#include "cli/VariantsCommand.h"
#include "cli/VariantsMerge.h"
#include "ivshadow/IvShadowInit.h"
#include "viewer/ViewerApplication.h"
#include "viewer/ViewerCommandLine.h"

#include <CLI/CLI.hpp>

#include <iostream>

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
    valid += (valid.empty() ? "" : ", ") + command->get_name();
  if (argc < 2) return "ivshadow: error: expected a command: " + valid;
  const std::string first = argv[1];
  if (first.empty() || first[0] == '-') return {};
  for (const CLI::App* command : app.get_subcommands(all))
    if (command->get_name() == first) return {};
  return "ivshadow: error: unknown command '" + first + "'; expected one of " + valid +
         " (ivshadow --help lists them)";
}

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"ivshadow: render Open Inventor scenes with transparent, coloured shadows",
               "ivshadow"};
  app.footer(footer(kOverview));
  app.set_version_flag("--version", std::string("ivshadow ") + ivshadow::version());
  app.require_subcommand(1);
  ivshadow::useProjectErrorFormat(app);

  ivshadow::RenderOptions render;
  CLI::App* renderCommand =
      app.add_subcommand("render", "Render an .iv file to a PNG or JPEG headlessly");
  renderCommand->footer(footer(kRenderExamples));
  renderCommand->add_option("scene", render.scene, "Open Inventor scene file (.iv)")->required();
  renderCommand->add_option("-o,--output", render.output, "Image to write: .png, .jpg or .jpeg")
      ->required();
  renderCommand->add_option("--size", render.size, "Image size WIDTHxHEIGHT")
      ->capture_default_str();
  renderCommand->add_option("--frames", render.frames, "Frames to render and time")
      ->capture_default_str();
  renderCommand->add_option("--stats", render.statsPath, "Write timing statistics as JSON");
  renderCommand
      ->add_option("--set", render.assignments,
                   "Assign NAME.field=VALUE (Inventor syntax) to DEF-named nodes")
      ->allow_extra_args(false);
  renderCommand->add_option("--transparency", render.transparency,
                            "Coin transparency type, e.g. BLEND, SORTED_LAYERS_BLEND");

  ivshadow::VariantsOptions variants;
  CLI::App* variantsCommand =
      app.add_subcommand("variants", "Render scripted variants of a scene (docs/VARIANTS.md)");
  variantsCommand->footer(footer(kVariantsExamples));
  variantsCommand->add_option("base", variants.base, "Open Inventor scene file (.iv)")->required();
  variantsCommand->add_option("variants", variants.variantsFile, "Variants file")->required();
  variantsCommand->add_option("-o,--output", variants.outputDir, "Directory to write to")
      ->required();
  variantsCommand->add_option("--size", variants.size, "Image size WIDTHxHEIGHT")
      ->capture_default_str();
  variantsCommand->add_option("--frames", variants.frames, "Frames to render and time")
      ->capture_default_str();
  variantsCommand->add_option("--jobs,-j", variants.jobs, "Variants rendered at once")
      ->capture_default_str();
  variantsCommand->add_option("--shard", variants.shard,
                              "Render part K of N: the variants whose index is K modulo N");
  variantsCommand->add_option("--only", variants.only, "Render only the variant NAME (repeatable)")
      ->allow_extra_args(false);
  variantsCommand->add_flag("--list", variants.list,
                            "Print each variant's name, a tab and the command rendering it alone");
  variantsCommand->add_option(
      "--slurm", variants.slurmDir,
      "Write Slurm job array and merge scripts to DIR instead of rendering");
  variantsCommand->add_option("--shards", variants.shards,
                              "--slurm: array tasks, one shard each (default 8)");
  variantsCommand->add_option("--limit", variants.limit,
                              "--slurm: array tasks running at once (default no limit)");

  ivshadow::VariantsMergeOptions merge;
  CLI::App* mergeCommand = app.add_subcommand(
      "variants-merge", "Write variants.csv and index.html from the manifests of every shard");
  mergeCommand->footer(footer(kMergeExamples));
  mergeCommand->add_option("dir", merge.outputDir, "The sweep's output directory")->required();
  mergeCommand->add_flag("--status", merge.statusOnly,
                         "Only print the done, failed and pending counts");

  ivshadow::ReferenceCommandOptions reference;
  CLI::App* referenceCommand = app.add_subcommand(
      "reference", "Render the exact picture on the CPU (Embree ray tracing) to compare with");
  referenceCommand->footer(footer(kReferenceExamples));
  referenceCommand->add_option("scene", reference.scene, "Open Inventor scene file (.iv)")
      ->required();
  referenceCommand
      ->add_option("-o,--output", reference.output, "Image to write: .png, .jpg or .jpeg")
      ->required();
  referenceCommand->add_option("--size", reference.size, "Image size WIDTHxHEIGHT")
      ->capture_default_str();
  referenceCommand->add_option("--pfm", reference.pfm,
                               "Also write the unrounded colours as a float PFM");
  referenceCommand
      ->add_option("--set", reference.assignments,
                   "Assign NAME.field=VALUE (Inventor syntax) to DEF-named nodes")
      ->allow_extra_args(false);
  CLI::Option* bounceOption =
      referenceCommand
          ->add_option("--bounce", reference.bounce,
                       "Rays per point of the one diffuse bounce of groups with bounce TRUE, "
                       "rounded up to a square (0: no bounce)")
          ->capture_default_str();
  referenceCommand->add_option("--threads", reference.threads, "Worker threads (0: every core)")
      ->capture_default_str();

  ivshadow::TradeOptions trade;
  CLI::App* tradeCommand = app.add_subcommand(
      "trade", "Time every deep shadow setting and measure its error against the reference");
  tradeCommand->footer(footer(kTradeExamples));
  tradeCommand->add_option("scene", trade.scene, "Open Inventor scene file (.iv)")->required();
  tradeCommand->add_option("-o,--output", trade.outputDir, "Directory for trade.csv, trade.png")
      ->required();
  tradeCommand->add_option("--size", trade.size, "Image size WIDTHxHEIGHT")->capture_default_str();
  tradeCommand->add_option("--resolution", trade.resolutions, "Cube face sizes, comma-separated")
      ->delimiter(',')
      ->capture_default_str();
  tradeCommand->add_option("--layers", trade.layers, "Layer caps, comma-separated")
      ->delimiter(',')
      ->capture_default_str();
  tradeCommand->add_option("--precision", trade.precisions, "half and/or float")
      ->delimiter(',')
      ->capture_default_str();
  tradeCommand
      ->add_option("--filter", trade.filters,
                   "none, bilinear (PCF over one texel) and/or pcf (3 x 3 texels)")
      ->delimiter(',')
      ->capture_default_str();
  tradeCommand->add_option("--slices", trade.slices, "Opacity map slice counts, comma-separated")
      ->delimiter(',')
      ->capture_default_str();
  tradeCommand
      ->add_option("--method", trade.methods,
                   "map, rays, volumes, opacity and/or tracer (the group traced whole)")
      ->delimiter(',')
      ->capture_default_str();
  tradeCommand->add_option("--frames", trade.frames, "Frames timed per setting (median)")
      ->capture_default_str();

  ivshadow::CompareOptions compare;
  CLI::App* compareCommand = app.add_subcommand(
      "compare", "Measure how far one picture (PNG or JPEG) is from another (the reference)");
  compareCommand->footer(footer(kCompareExamples));
  compareCommand->add_option("reference", compare.reference, "The picture taken as right")
      ->required();
  compareCommand->add_option("candidate", compare.candidate, "The picture measured")->required();
  compareCommand->add_option("--diff", compare.diffPath,
                             "Write a heat map of the error (.png or .jpg)");
  compareCommand->add_option("--scale", compare.scale,
                             "Heat map: error in 8-bit steps shown as white (0: the largest)");
  compareCommand->add_option("--json", compare.jsonPath, "Write the metrics as JSON");

  ivshadow::ViewerOptions view;
  CLI::App* viewCommand = app.add_subcommand("view", "Open an .iv file in the viewer");
  viewCommand->footer(footer(kViewExamples));
  ivshadow::addViewerOptions(*viewCommand, view);

  if (const std::string unknown = unknownCommand(argc, argv, app); !unknown.empty()) {
    std::cerr << unknown << '\n';
    return 2;
  }
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    const int status = app.exit(error);
    return status == 0 ? 0 : 2;
  }
  if (renderCommand->parsed()) return ivshadow::runRender(render);
  if (variantsCommand->parsed()) return ivshadow::runVariants(variants);
  if (mergeCommand->parsed()) return ivshadow::runVariantsMerge(merge);
  if (compareCommand->parsed()) return ivshadow::runCompare(compare);
  if (referenceCommand->parsed()) {
    reference.bounceGiven = bounceOption->count() > 0;
    return ivshadow::runReference(reference);
  }
  if (tradeCommand->parsed()) return ivshadow::runTrade(trade);
  return ivshadow::runViewer(view, argv[0]);
}
