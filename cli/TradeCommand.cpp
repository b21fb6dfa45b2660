#include "cli/TradeCommand.h"

#include "cli/ExitStatus.h"
#include "cli/OpenRenderer.h"
#include "cli/OutputDirectory.h"
#include "cli/ProgressBar.h"
#include "cli/ReferenceOverlay.h"
#include "cli/RenderMemory.h"
#include "cli/TradePlot.h"
#include "gl/GlCapabilities.h"
#include "gl/ShaderConstants.h"
#include "headless/FrameStatistics.h"
#include "headless/OffscreenRenderer.h"
#include "image_files/AtomicFile.h"
#include "image_files/CommandPaths.h"
#include "image_files/ImageComparison.h"
#include "image_files/ImageSize.h"
#include "image_files/MemoryBudget.h"
#include "image_files/OutputFiles.h"
#include "image_files/PngFile.h"
#include "ivshadow/DeepShadowStatistics.h"
#include "ivshadow/IvShadowInit.h"
#include "ivshadow/SoDeepShadowLight.h"
#include "ivshadow/SoTransparentShadowGroup.h"
#include "nodes/NodesOfType.h"
#include "reference/ReferenceRenderer.h"
#include "scene/InputError.h"
#include "scene_input/SceneLoader.h"
#include "scene_input/ViewSetup.h"

#include <Inventor/SbViewportRegion.h>
#include <Inventor/SoPath.h>
#include <Inventor/actions/SoSearchAction.h>
#include <Inventor/nodes/SoSeparator.h>

#include <algorithm>
#include <chrono>
#include <filesystem>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace ivshadow {
namespace {

template <typename Node>
std::vector<Node*> allNodes(SoNode* root) {
  std::vector<Node*> nodes;
  forEachNodeOfType<Node>(root, [&nodes](Node& node) { nodes.push_back(&node); });
  return nodes;
}

struct Setting {
  std::string label;
  // SoDeepShadowLight::Method: MAP and OPACITY_MAP sweep the map's settings; RAYS and
  // VOLUMES, exact, have none.
  int method = SoDeepShadowLight::MAP;
  int resolution = 0;
  int layers = 0;  // an opacity map's: its slices
  std::string precision;
  std::string filter;
  // The group traced whole (SoTransparentShadowGroup renderer TRACER): the lights' fields do
  // not apply.
  bool tracer = false;
};

struct Row {
  Setting setting;
  std::string kind;  // one of trade_kind (cli/TradePlot.h)
  double buildMs = 0.0;
  double frameMs = 0.0;
  std::uint64_t bytes = 0;
  ImageComparison metrics;
};

void checkList(const std::vector<std::string>& values, const std::vector<std::string>& allowed,
               const std::string& option) {
  for (const std::string& value : values)
    if (std::find(allowed.begin(), allowed.end(), value) == allowed.end())
      throw InputError(option + " " + value + ": error: expected one or more of " +
                       joinedList(allowed, "or") + ", comma-separated");
}

double frameMedian(OffscreenRenderer& renderer, SoNode* root, int frames) {
  std::vector<double> wall;
  for (int i = 0; i < frames; ++i) wall.push_back(renderer.render(root).wallMs);
  return FrameStatistics::median(wall);
}

std::string csvLine(const Row& row) {
  std::ostringstream out;
  out << std::setprecision(6) << '"' << row.setting.label << "\"," << row.kind << ','
      << row.setting.resolution << ',' << row.setting.layers << ',' << row.setting.precision << ','
      << row.setting.filter << ',' << row.buildMs << ',' << row.frameMs << ','
      << row.buildMs + row.frameMs << ',' << row.metrics.all.rmse << ',' << row.metrics.all.psnr
      << ',' << row.metrics.all.maxError << ',' << row.metrics.all.shareAbove2 << ',' << row.bytes;
  return out.str();
}

}  // namespace

std::string joinedList(const std::vector<std::string>& values, const std::string& last) {
  std::string out;
  for (std::size_t i = 0; i < values.size(); ++i)
    out += (i == 0 ? "" : i + 1 == values.size() ? " " + last + " " : ", ") + values[i];
  return out;
}

namespace {

// Which methods --method asks for.
struct Methods {
  bool maps = false, rays = false, volumes = false, opacity = false, tracer = false;
};

// Checks every option that needs no scene; returns the methods asked for.
Methods checkTradeOptions(const TradeOptions& options) {
  if (options.frames < 1)
    throw InputError("--frames " + std::to_string(options.frames) +
                     ": error: expected a whole number of at least 1");
  for (int r : options.resolutions)
    if (r < 1) throw InputError("--resolution " + std::to_string(r) + ": error: expected >= 1");
  for (int l : options.layers)
    if (l < 1 || l > kMaxMapLayers)
      throw InputError("--layers " + std::to_string(l) + ": error: expected 1 .. " +
                       std::to_string(kMaxMapLayers));
  checkList(options.precisions, kTradePrecisions, "--precision");
  checkList(options.filters, kTradeFilters, "--filter");
  for (int n : options.slices)
    if (n < 1 || n > kMaxOpacitySlices)
      throw InputError("--slices " + std::to_string(n) + ": error: expected 1 .. " +
                       std::to_string(kMaxOpacitySlices));
  checkList(options.methods, kTradeMethods, "--method");
  const auto asked = [&](const char* method) {
    return std::count(options.methods.begin(), options.methods.end(), method) > 0;
  };
  return {asked("map"), asked("rays"), asked("volumes"), asked("opacity"), asked("tracer")};
}

// The settings to measure: the exact ones, then each map's and opacity map's sweep.
std::vector<Setting> tradeSettings(const TradeOptions& options, const Methods& asked) {
  std::vector<Setting> settings;
  if (asked.rays)
    settings.push_back(Setting{"rays (exact)", SoDeepShadowLight::RAYS, 0, 0, "", ""});
  if (asked.tracer) {
    Setting traced{"group traced (TRACER)", SoDeepShadowLight::RAYS, 0, 0, "", ""};
    traced.tracer = true;
    settings.push_back(traced);
  }
  if (asked.volumes)
    settings.push_back(
        Setting{"shadow volumes (exact, hard)", SoDeepShadowLight::VOLUMES, 0, 0, "", ""});
  for (int resolution : asked.maps ? options.resolutions : std::vector<int>{})
    for (int layers : options.layers)
      for (const std::string& precision : options.precisions)
        for (const std::string& filter : options.filters)
          settings.push_back(Setting{std::to_string(resolution) + " " + std::to_string(layers) +
                                         "L " + precision + (filter == "none" ? "" : " " + filter),
                                     SoDeepShadowLight::MAP, resolution, layers, precision,
                                     filter});
  for (int resolution : asked.opacity ? options.resolutions : std::vector<int>{})
    for (int slices : options.slices)
      for (const std::string& precision : options.precisions)
        for (const std::string& filter : options.filters)
          settings.push_back(
              Setting{"opacity " + std::to_string(resolution) + " " + std::to_string(slices) +
                          "S " + precision + (filter == "none" ? "" : " " + filter),
                      SoDeepShadowLight::OPACITY_MAP, resolution, slices, precision, filter});
  return settings;
}

// The scene's deep shadow nodes, which each setting sets.
struct TradeNodes {
  std::vector<SoDeepShadowLight*> lights;
  std::vector<SoTransparentShadowGroup*> groups;
};

TradeNodes tradeNodes(const std::string& scenePath, SoNode* root) {
  TradeNodes nodes{allNodes<SoDeepShadowLight>(root), allNodes<SoTransparentShadowGroup>(root)};
  if (nodes.lights.empty() || nodes.groups.empty())
    throw InputError(scenePath +
                     ": error: expected a DeepShadowLight inside a TransparentShadowGroup; "
                     "there is no deep shadow setting to trade");
  return nodes;
}

Row baselineRow(const std::string& label, double frameMs, const ImageComparison& metrics) {
  Row row;
  row.setting.label = label;
  row.kind = trade_kind::kBaseline;
  row.frameMs = frameMs;
  row.metrics = metrics;
  return row;
}

// The exact picture, with what GL draws and the tracer leaves out drawn over it, and the time
// the reference took.
Image exactPicture(const TradeOptions& options, const ImageSize& size, SoNode* root,
                   double& referenceMs) {
  ReferenceOptions referenceOptions;
  referenceOptions.width = size.width;
  referenceOptions.height = size.height;
  const auto start = std::chrono::steady_clock::now();
  std::optional<ReferenceResult> reference = renderReference(root, referenceOptions);
  referenceMs =
      std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  if (const std::string error = drawUntracedOver(root, referenceOptions.background, *reference);
      !error.empty())
    std::cerr << options.scene << ": warning: the shapes GL draws are missing from the "
              << "reference: " << error << '\n';
  return reference->image.toImage();
}

void applySetting(const Setting& setting, const TradeNodes& nodes) {
  for (SoTransparentShadowGroup* group : nodes.groups)
    group->renderer.setValue(setting.tracer ? SoTransparentShadowGroup::TRACER
                                            : SoTransparentShadowGroup::RASTER);
  for (SoDeepShadowLight* light : nodes.lights) {
    light->method.setValue(setting.method);
    const bool opacityMap = setting.method == SoDeepShadowLight::OPACITY_MAP;
    if (setting.method != SoDeepShadowLight::MAP && !opacityMap) continue;
    light->resolution.setValue(setting.resolution);
    (opacityMap ? light->slices : light->maxLayers).setValue(setting.layers);
    light->precision.setValue(setting.precision == "half" ? SoDeepShadowLight::HALF
                                                          : SoDeepShadowLight::FLOAT);
    // bilinear: PCF over one texel; pcf: over filterSize's default, 3 x 3.
    light->filter.setValue(setting.filter == "none" ? SoDeepShadowLight::NONE
                                                    : SoDeepShadowLight::PCF);
    light->filterSize.setValue(setting.filter == "bilinear" ? 1 : 3);
  }
}

const char* kindOf(const Setting& setting) {
  return setting.tracer                                     ? trade_kind::kTracer
         : setting.method == SoDeepShadowLight::RAYS        ? trade_kind::kRays
         : setting.method == SoDeepShadowLight::VOLUMES     ? trade_kind::kVolumes
         : setting.method == SoDeepShadowLight::OPACITY_MAP ? trade_kind::kOpacityMap
                                                            : trade_kind::kMap;
}

// Renders one setting (already applied) and measures its build, its frame, what it keeps and
// its error against the exact picture.
Row measureSetting(const Setting& setting, const TradeNodes& nodes, OffscreenRenderer& renderer,
                   SoNode* root, int frames, const Image& exact) {
  Row row;
  row.setting = setting;
  row.kind = kindOf(setting);
  const bool wholeFrame = setting.method != SoDeepShadowLight::MAP;
  // Each build is timed on its own (touching a light forces one), median of --frames.
  // A deep shadow map is built when the light moves: its build waits for each pass.
  // Traced shadows are traced again, or the volumes drawn, within the frame, and GL draws
  // the volumes and an opacity map (which waits for nothing) after their commands are
  // sent: for those the moved light's whole frame is timed (to glFinish), less the frame
  // without a change measured below.
  std::vector<double> builds;
  for (int i = 0; i < frames; ++i) {
    if (i > 0)
      for (SoDeepShadowLight* light : nodes.lights) light->location.touch();
    const double wallMs = renderer.render(root).wallMs;
    const DeepShadowStatistics built = collectDeepShadowStatistics(root);
    builds.push_back(wholeFrame ? wallMs : built.lastBuildMs);
  }
  row.buildMs = FrameStatistics::median(builds);
  const DeepShadowStatistics stats = collectDeepShadowStatistics(root);
  for (const DeepShadowLightStatistics& light : stats.lights) row.bytes += light.bytes;
  if (setting.method == SoDeepShadowLight::RAYS && !setting.tracer)
    row.bytes = stats.bvhBytes;  // the casters' BVH instead of a map
  row.frameMs = frameMedian(renderer, root, frames);
  if (wholeFrame) row.buildMs = std::max(0.0, row.buildMs - row.frameMs);
  row.metrics = ImageComparison::compare(exact, renderer.read(), "reference", "render");
  return row;
}

// The reference, the table and the chart, together or none.
void writeTrade(const TradeOptions& options, const std::string& title, const Image& exact,
                const std::vector<Row>& rows) {
  std::ostringstream csv;
  // map_bytes: what the setting keeps between frames (the map, or for rays the BVH);
  // layers: for an opacity map its slices.
  csv << "setting,kind,resolution,layers,precision,filter,build_ms,frame_ms_median,"
         "rebuild_frame_ms,rmse,psnr_db,max_abs_error,share_above_2,map_bytes\n";
  std::vector<TradePoint> points;
  for (const Row& row : rows) {
    csv << csvLine(row) << '\n';
    points.push_back(TradePoint{row.setting.label, row.kind, row.buildMs + row.frameMs,
                                row.metrics.all.rmse, row.metrics.all.psnr,
                                row.kind == trade_kind::kBaseline, false});
  }
  markParetoFront(points);
  OutputFiles outputs;
  outputs.add(options.outputDir + "/reference.png", [&](const std::string& file) {
    writePngTo(file, options.outputDir + "/reference.png", exact);
  });
  outputs.addText(options.outputDir + "/trade.csv", csv.str());
  addTradePlot(outputs, options.outputDir + "/trade.svg", title, points);
  outputs.commit();
}

}  // namespace

int runTrade(const TradeOptions& options) {
  return withExitStatus([&] {
    const ImageSize size = ImageSize::parse(options.size, "--size");
    const Methods asked = checkTradeOptions(options);
    const OutputDirectory outputDir{"-o", options.outputDir,
                                    "trade.csv, trade.svg and reference.png"};
    outputDir.check();
    CommandPaths()
        .input("scene", options.scene)
        .output("-o", options.outputDir + "/trade.csv")
        .output("-o", options.outputDir + "/trade.svg")
        .output("-o", options.outputDir + "/reference.png")
        .check();

    init();
    LoadedScene scene = loadScene(options.scene);
    for (const std::string& warning : scene.warnings) std::cerr << warning << '\n';
    const TradeNodes nodes = tradeNodes(options.scene, scene.root.get());
    // One process holds the reference and the renders, the traced setting's among them, at
    // once.
    const MemoryCost render =
        RenderMemory::of(scene.root.get(), false, asked.rays || asked.volumes || asked.tracer).cost;
    MemoryBudget::check(size,
                        {kReferenceCost.bytesPerPixel + render.bytesPerPixel,
                         kReferenceCost.fixedBytes + render.fixedBytes},
                        "the trade (the reference and the renders in one process)", 1,
                        MemoryBudget::available());
    const ViewSetup view = ViewSetup::prepare(
        scene.root.get(), SbViewportRegion(short(size.width), short(size.height)));
    SoNode* root = view.root.get();

    std::unique_ptr<OffscreenRenderer> renderer = openRenderer(size);
    if (!renderer) return 3;
    // Only good input makes the directory; its files are written once the sweep is done.
    outputDir.create();
    AtomicFile::checkWritable(options.outputDir + "/trade.csv", "the table");

    const std::vector<Setting> settings = tradeSettings(options, asked);
    const int total = int(settings.size()) + 2;
    ProgressBar bar;
    int done = 0;
    double referenceMs = 0.0;
    const Image exact = exactPicture(options, size, root, referenceMs);
    bar.update(++done, total, "exact reference");
    std::vector<Row> rows{
        baselineRow("exact (CPU reference)", referenceMs,
                    ImageComparison::compare(exact, exact, "reference", "reference"))};

    for (SoTransparentShadowGroup* group : nodes.groups) group->isActive.setValue(FALSE);
    renderer->render(root);
    const double plainMs = frameMedian(*renderer, root, options.frames);
    rows.push_back(
        baselineRow("no shadows (plain Coin)", plainMs,
                    ImageComparison::compare(exact, renderer->read(), "reference", "plain")));
    bar.update(++done, total, rows.back().setting.label);
    // The first render with the group compiles its shaders; no setting should pay for that.
    // GL's path and the map, which have the shaders, named: the defaults, AUTO, may trace
    // instead (and say so).
    for (SoTransparentShadowGroup* group : nodes.groups) {
      group->isActive.setValue(TRUE);
      group->renderer.setValue(SoTransparentShadowGroup::RASTER);
    }
    for (SoDeepShadowLight* light : nodes.lights) light->method.setValue(SoDeepShadowLight::MAP);
    renderer->render(root);

    for (const Setting& setting : settings) {
      applySetting(setting, nodes);
      rows.push_back(measureSetting(setting, nodes, *renderer, root, options.frames, exact));
      bar.update(++done, total, setting.label);
    }
    writeTrade(options,
               std::filesystem::path(options.scene).filename().string() + " at " + size.toString() +
                   " on " + renderer->capabilities().renderer,
               exact, rows);
    // The count the progress ran to: every row of the table, the baselines with the settings.
    std::cout << "wrote " << options.outputDir << "/trade.csv and trade.svg: " << rows.size()
              << " rows, " << settings.size() << " shadow settings and "
              << rows.size() - settings.size() << " baselines (the reference took " << std::fixed
              << std::setprecision(1) << referenceMs << " ms)\n";
    return 0;
  });
}

}  // namespace ivshadow
