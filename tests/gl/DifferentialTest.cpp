// One scene, one picture (issue 36): every bundled scene and a generated set (nested groups,
// lights of every kind, cameras at the edges, lines and text; tests/support/RandomScene.h),
// drawn by every path of cli/MethodAgreement.h and by the reference; each agrees with the
// reference within its documented error. IVSHADOW_DIFFERENTIAL_SCENES sets how many generated
// scenes (CI: 12; bench/differential.sh: hundreds, with the corpus's wrapped models).
#include "cli/MethodAgreement.h"
#include "cli/ReferenceOverlay.h"
#include "image_files/ImageComparison.h"
#include "image_files/PngFile.h"
#include "ivshadow/IvShadowInit.h"
#include "ivshadow/SoDeepShadowDirectionalLight.h"
#include "ivshadow/SoDeepShadowLight.h"
#include "ivshadow/SoDeepShadowSpotLight.h"
#include "ivshadow/SoTransparentShadowGroup.h"
#include "reference/ReferenceRenderer.h"
#include "scene_input/CoinMessageCapture.h"
#include "scene_input/ViewSetup.h"
#include "tests/gl/CheckedRenderer.h"
#include "tests/gl/ShadowScene.h"
#include "tests/support/RandomScene.h"
#include "tests/support/TestSupport.h"

#include <Inventor/SbViewportRegion.h>
#include <Inventor/SoDB.h>
#include <Inventor/SoInput.h>
#include <Inventor/actions/SoSearchAction.h>
#include <Inventor/nodes/SoSeparator.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace ivshadow::test {
namespace {

constexpr int kWidth = 96;
constexpr int kHeight = 72;

// Sets `field` of every node of `type` under `root` to `value` (Inventor syntax).
void setAll(SoNode* root, SoType type, const char* field, const char* value) {
  SoSearchAction search;
  search.setType(type);
  search.setInterest(SoSearchAction::ALL);
  search.setSearchingAll(TRUE);
  search.apply(root);
  for (int i = 0; i < search.getPaths().getLength(); ++i)
    search.getPaths()[i]->getTail()->set((std::string(field) + " " + value).c_str());
}

struct Drawn {
  Image image;
  std::string warnings;
};

Drawn draw(const std::string& text, const MethodAgreement* path) {
  init();
  CoinMessageCapture messages;
  Drawn drawn;
  SoSeparator* scene = readIv(text);
  // The bounce traces random rays, and has its own tests (BounceTest): left out here.
  setAll(scene, SoTransparentShadowGroup::getClassTypeId(), "bounce", "FALSE");
  if (path != nullptr) {
    setAll(scene, SoTransparentShadowGroup::getClassTypeId(), "renderer", path->renderer);
    if (*path->method != '\0')
      for (SoType type :
           {SoTransparentShadowGroup::getClassTypeId(), SoDeepShadowLight::getClassTypeId(),
            SoDeepShadowSpotLight::getClassTypeId(),
            SoDeepShadowDirectionalLight::getClassTypeId()})
        setAll(scene, type, "method", path->method);
  }
  const ViewSetup view = ViewSetup::prepare(scene, SbViewportRegion(kWidth, kHeight));
  if (path == nullptr) {
    ReferenceOptions options;
    options.width = kWidth;
    options.height = kHeight;
    options.bounceSamples = 16;
    std::optional<ReferenceResult> result = renderReference(view.root.get(), options);
    if (result) {
      const std::string error = drawUntracedOver(view.root.get(), options.background, *result);
      if (!error.empty()) drawn.warnings += error + "\n";
      drawn.image = result->image.toImage();
    }
  } else {
    std::string error;
    auto renderer = CheckedRenderer::create(kWidth, kHeight, error);
    if (!renderer) throw std::runtime_error(error);
    renderer->render(view.root.get());
    drawn.image = renderer->read();
  }
  scene->unref();
  for (const CoinMessageCapture::Message& m : messages.messages())
    if (!m.isError && m.text.find("method AUTO uses") == std::string::npos)
      drawn.warnings += m.text + "\n";
  return drawn;
}

struct Scene {
  std::string name;
  std::string text;
};

std::vector<Scene> scenes() {
  std::vector<Scene> result;
  namespace fs = std::filesystem;
  for (const fs::directory_entry& entry : fs::directory_iterator(scenesDir())) {
    const std::string name = entry.path().filename().string();
    if (entry.path().extension() != ".iv" || name.rfind("stress_", 0) == 0) continue;
    const std::string text = readText(entry.path().string());
    // Only what the plugin draws: a scene without a group or a peeling separator is Coin's.
    if (text.find("TransparentShadowGroup") == std::string::npos &&
        text.find("PeelingSeparator") == std::string::npos)
      continue;
    result.push_back({name, text});
  }
  // The corpus's models as its test wrapped them (bench/differential.sh).
  if (const char* corpus = std::getenv("IVSHADOW_DIFFERENTIAL_CORPUS"))
    for (const fs::directory_entry& entry : fs::directory_iterator(corpus)) {
      const fs::path wrapped = entry.path() / "wrapped.iv";
      if (!fs::exists(wrapped)) continue;
      result.push_back({entry.path().filename().string(), readText(wrapped.string())});
    }
  const char* count = std::getenv("IVSHADOW_DIFFERENTIAL_SCENES");
  const int generated = count != nullptr ? std::atoi(count) : 12;
  for (int seed = 1; seed <= generated; ++seed)
    result.push_back({"random " + std::to_string(seed), randomScene(std::uint32_t(seed))});
  return result;
}

TEST(Differential, EveryPathAgreesWithTheReferenceWithinItsDocumentedError) {
  std::ostringstream report;
  int failures = 0;
  for (const Scene& scene : scenes()) {
    const Drawn reference = draw(scene.text, nullptr);
    for (const MethodAgreement& path : kMethodAgreements) {
      const Drawn drawn = draw(scene.text, &path);
      const ImageComparison c =
          ImageComparison::compare(drawn.image, reference.image, path.path, "reference");
      const bool agrees = c.all.psnr >= path.minPsnrDb && c.all.shareAbove2 <= path.maxShareAbove2;
      // Below its floor, a method may have said why (a warning naming it).
      const bool saidWhy =
          (*path.method != '\0' &&
           drawn.warnings.find(std::string("method ") + path.method) != std::string::npos) ||
          drawn.warnings.find("too coarse to order") != std::string::npos;
      report << scene.name << ' ' << path.path << ' ' << c.all.psnr << " dB "
             << 100.0 * c.all.shareAbove2 << " %"
             << (agrees    ? ""
                 : saidWhy ? "  below, said why"
                           : "  BELOW")
             << '\n';
      if (!agrees && !saidWhy) {
        ++failures;
        // The two pictures, for a look: <scene>-<path>.png and <scene>-reference.png.
        std::string stem = outputDir() + "/" + scene.name;
        std::replace(stem.begin() + std::ptrdiff_t(outputDir().size()) + 1, stem.end(), ' ', '_');
        writePng(stem + "-" + path.path + ".png", drawn.image);
        writePng(stem + "-reference.png", reference.image);
        report << drawn.warnings;
      }
    }
  }
  std::ofstream(outputDir() + "/report.txt") << report.str();
  std::cout << report.str();
  EXPECT_EQ(failures, 0) << report.str();
}

}  // namespace
}  // namespace ivshadow::test
