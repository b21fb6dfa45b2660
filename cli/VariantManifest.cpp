#include "cli/VariantManifest.h"

#include "image/AtomicFile.h"

#include <fstream>

namespace ivshadow {

std::string VariantManifest::path(const std::string& outputDir, const std::string& variant) {
  return outputDir + "/manifests/" + variant + ".json";
}

std::optional<VariantManifest> VariantManifest::read(const std::string& outputDir,
                                                     const std::string& variant) {
  std::ifstream in(path(outputDir, variant));
  if (!in) return std::nullopt;
  const nlohmann::json json = nlohmann::json::parse(in, nullptr, false);
  if (!json.is_object() || json.value("variant", std::string()) != variant) return std::nullopt;
  VariantManifest manifest;
  manifest.variant = variant;
  manifest.assignments = json.value("assignments", std::vector<std::string>());
  manifest.size = json.value("size", std::string());
  manifest.frames = json.value("frames", 0);
  manifest.hash = json.value("hash", std::string());
  manifest.exitCode = json.value("exit_code", -1);
  manifest.error = json.value("error", std::string());
  manifest.stats = json.contains("stats") ? json["stats"] : nlohmann::json();
  manifest.seconds = json.value("seconds", 0.0);
  manifest.host = json.value("host", std::string());
  return manifest;
}

void VariantManifest::write(const std::string& outputDir) const {
  const nlohmann::json json = {{"variant", variant},    {"assignments", assignments},
                               {"size", size},          {"frames", frames},
                               {"hash", hash},          {"status", ok() ? "ok" : "failed"},
                               {"exit_code", exitCode}, {"error", error},
                               {"seconds", seconds},    {"host", host},
                               {"stats", stats}};
  writeTextFileAtomically(path(outputDir, variant), json.dump(2) + "\n");
}

}  // namespace ivshadow
