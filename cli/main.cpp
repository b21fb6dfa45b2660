#include "cli/CompareCommand.h"
#include "cli/ReferenceCommand.h"
#include "cli/RenderCommand.h"
#include "cli/TradeCommand.h"
#include "cli/VariantsCommand.h"
#include "ivshadow/IvShadowInit.h"
#include "viewer/ViewerApplication.h"
#include "viewer/ViewerCommandLine.h"

#include <CLI/CLI.hpp>

#include <iostream>

namespace {

const char* kExamples = R"(Examples:
  ivshadow render iv_scenes/glass_over_floor.iv -o glass.png
  ivshadow render scene.iv -o big.png --size 1920x1080 --frames 20 --stats stats.json
  ivshadow render scene.iv -o red.png --set Glass.diffuseColor="1 0 0" --set Lamp.intensity=0.5
  ivshadow render scene.iv -o coin.png --transparency SORTED_LAYERS_BLEND
  ivshadow variants iv_scenes/coloured_shadows.iv iv_scenes/coloured_shadows.variants -o out/v
  ivshadow reference scene.iv -o exact.png --size 640x480 --pfm exact.pfm
  ivshadow trade iv_scenes/coloured_shadows.iv -o out/trade --layers 1,4 --filter none
  ivshadow compare reference.png render.png --diff diff.png
  ivshadow view iv_scenes/glass_over_floor.iv

Exit status: 0 success, 2 bad input (file, field, option), 3 no GL context or display,
1 any other failure. No output file is written unless the command succeeds.)";

}  // namespace

int main(int argc, char** argv) {
  CLI::App app{"ivshadow: render Open Inventor scenes with transparent, coloured shadows",
               "ivshadow"};
  app.footer(kExamples);
  app.set_version_flag("--version", std::string("ivshadow ") + ivshadow::version());
  app.require_subcommand(1);

  ivshadow::RenderOptions render;
  CLI::App* renderCommand = app.add_subcommand("render", "Render an .iv file to a PNG headlessly");
  renderCommand->add_option("scene", render.scene, "Open Inventor scene file (.iv)")->required();
  renderCommand->add_option("-o,--output", render.output, "PNG file to write")->required();
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

  ivshadow::ReferenceCommandOptions reference;
  CLI::App* referenceCommand = app.add_subcommand(
      "reference", "Render the exact picture on the CPU (Embree ray tracing) to compare with");
  referenceCommand->add_option("scene", reference.scene, "Open Inventor scene file (.iv)")
      ->required();
  referenceCommand->add_option("-o,--output", reference.output, "PNG file to write")->required();
  referenceCommand->add_option("--size", reference.size, "Image size WIDTHxHEIGHT")
      ->capture_default_str();
  referenceCommand->add_option("--pfm", reference.pfm,
                               "Also write the unrounded colours as a float PFM");
  referenceCommand
      ->add_option("--set", reference.assignments,
                   "Assign NAME.field=VALUE (Inventor syntax) to DEF-named nodes")
      ->allow_extra_args(false);
  referenceCommand->add_option("--threads", reference.threads, "Worker threads (0: every core)")
      ->capture_default_str();

  ivshadow::TradeOptions trade;
  CLI::App* tradeCommand = app.add_subcommand(
      "trade", "Time every deep shadow setting and measure its error against the reference");
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
  tradeCommand->add_option("--filter", trade.filters, "none and/or pcf")
      ->delimiter(',')
      ->capture_default_str();
  tradeCommand->add_option("--method", trade.methods, "map and/or rays")
      ->delimiter(',')
      ->capture_default_str();
  tradeCommand->add_option("--frames", trade.frames, "Frames timed per setting (median)")
      ->capture_default_str();

  ivshadow::CompareOptions compare;
  CLI::App* compareCommand =
      app.add_subcommand("compare", "Measure how far one PNG is from another (the reference)");
  compareCommand->add_option("reference", compare.reference, "The picture taken as right")
      ->required();
  compareCommand->add_option("candidate", compare.candidate, "The picture measured")->required();
  compareCommand->add_option("--diff", compare.diffPath, "Write a heat map of the error (PNG)");
  compareCommand->add_option("--scale", compare.scale,
                             "Heat map: error in 8-bit steps shown as white (0: the largest)");
  compareCommand->add_option("--json", compare.jsonPath, "Write the metrics as JSON");

  ivshadow::ViewerOptions view;
  CLI::App* viewCommand = app.add_subcommand("view", "Open an .iv file in the viewer");
  ivshadow::addViewerOptions(*viewCommand, view);

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    const int status = app.exit(error);
    return status == 0 ? 0 : 2;
  }
  if (renderCommand->parsed()) return ivshadow::runRender(render);
  if (variantsCommand->parsed()) return ivshadow::runVariants(variants);
  if (compareCommand->parsed()) return ivshadow::runCompare(compare);
  if (referenceCommand->parsed()) return ivshadow::runReference(reference);
  if (tradeCommand->parsed()) return ivshadow::runTrade(trade);
  return ivshadow::runViewer(view, argv[0]);
}
