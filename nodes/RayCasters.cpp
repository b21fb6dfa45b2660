#include "nodes/RayCasters.h"

#include "ivshadow/DeepShadowStatistics.h"
#include "raytrace/EmbreeHandles.h"

#include <Inventor/errors/SoDebugError.h>

#include <unistd.h>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>

namespace ivshadow {
namespace {

// Embree may use at most half the machine's memory (IVSHADOW_EMBREE_MEMORY_LIMIT, in bytes,
// overrides it): past that a light keeps its map rather than the process running out.
std::int64_t embreeMemoryLimit() {
  const std::int64_t half =
      std::int64_t(sysconf(_SC_PHYS_PAGES)) * std::int64_t(sysconf(_SC_PAGE_SIZE)) / 2;
  const char* text = std::getenv("IVSHADOW_EMBREE_MEMORY_LIMIT");
  if (text == nullptr) return half;
  char* end = nullptr;
  const long long bytes = std::strtoll(text, &end, 10);
  if (end == text || *end != '\0' || bytes <= 0) {
    SoDebugError::postWarning("SoDeepShadowLight",
                              "IVSHADOW_EMBREE_MEMORY_LIMIT is '%s', expected a number of bytes "
                              "above 0; using half the memory",
                              text);
    return half;
  }
  return bytes;
}

struct SharedDevice {
  EmbreeMemory memory;
  EmbreeDevice device;
  std::string error;  // why there is no device
};

// Made on first use and never freed: scenes of nodes that outlive static destruction still
// report their memory to `memory` through the device's monitor.
SharedDevice& sharedDevice() {
  static SharedDevice* shared = [] {
    auto* made = new SharedDevice;
    made->memory.limit = embreeMemoryLimit();
    // IVSHADOW_FAIL_EMBREE=device: the failure tests force, taking the path of a machine
    // where Embree cannot start (no supported CPU, no memory).
    // An unknown word is reported rather than ignored, as IVSHADOW_FAIL_GL's: a test whose
    // knob was misspelt would otherwise pass without forcing anything.
    const char* fail = std::getenv("IVSHADOW_FAIL_EMBREE");
    const bool forced = fail != nullptr && std::string(fail) == "device";
    if (fail != nullptr && *fail != '\0' && !forced)
      std::fprintf(stderr, "ivshadow: warning: IVSHADOW_FAIL_EMBREE: '%s' is not device; ignored\n",
                   fail);
    if (forced)
      made->error = "Embree could not create a device (forced by IVSHADOW_FAIL_EMBREE=device)";
    else
      made->device = createEmbreeDevice(made->error, &made->memory);
    return made;
  }();
  return *shared;
}

double millisecondsSince(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start)
      .count();
}

}  // namespace

bool RayCasters::ready(const SceneTriangles& casters, std::uint64_t version, const SoLight* light,
                       const std::string& lightName, const char* instead,
                       DeepShadowStatistics& statistics) {
  if (error_.empty() && scene_ && version_ != version) {
    // The same triangles recoloured or moved keep their tree.
    const auto start = std::chrono::steady_clock::now();
    const CasterScene::Update update = scene_->update(casters);
    if (update != CasterScene::Update::Rebuild) {
      version_ = version;
      if (update == CasterScene::Update::Refit) {
        ++statistics.bvhRefits;
        statistics.bvhBuildMs = millisecondsSince(start);
      }
    }
  }
  if (error_.empty() && (!scene_ || version_ != version)) {
    const auto start = std::chrono::steady_clock::now();
    scene_.reset();
    SharedDevice& shared = sharedDevice();
    // What the device holds without this group's scene: the rest is this group's.
    const std::int64_t before = shared.memory.bytes.load();
    if (shared.device)
      scene_ = CasterScene::build(shared.device.get(), casters, error_);
    else
      error_ = shared.error;
    version_ = version;
    ++statistics.bvhBuilds;
    statistics.bvhBuildMs = millisecondsSince(start);
    statistics.bvhBytes =
        std::uint64_t(std::max<std::int64_t>(shared.memory.bytes.load() - before, 0));
    if (!scene_ && error_.empty()) error_ = "Embree failed";
  }
  if (scene_) return true;
  // Once per light and what is done instead: a light whose RAYS fell back to its map still
  // says that its group's bounce is dropped.
  if (warned_.emplace(light, instead).second)
    SoDebugError::postWarning("SoDeepShadowLight", "light %s: cannot trace shadow rays (%s); %s",
                              lightName.c_str(), error_.c_str(), instead);
  return false;
}

}  // namespace ivshadow
