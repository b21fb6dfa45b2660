#include "cli/VariantManifest.h"

#include "cli/JsonFields.h"
#include "image_files/AtomicFile.h"
#include "scene/InputError.h"

#include <filesystem>

namespace ivshadow {

std::string VariantManifest::path(const std::string& outputDir, const std::string& variant) {
  return outputDir + "/manifests/" + variant + ".json";
}

std::optional<VariantManifest> VariantManifest::read(const std::string& outputDir,
                                                     const std::string& variant) {
  const std::string file = path(outputDir, variant);
  std::error_code ec;
  if (!std::filesystem::exists(file, ec)) return std::nullopt;
  const nlohmann::json json = readJsonObject(file, "the manifest of variant " + variant);
  const JsonFields fields(json, file);
  VariantManifest manifest;
  manifest.variant = fields.text("variant");
  if (manifest.variant != variant)
    throw InputError(file + ": error: the manifest names the variant \"" + manifest.variant +
                     "\", not \"" + variant + "\" (copied from another sweep?)");
  manifest.assignments = fields.texts("assignments");
  manifest.size = fields.text("size");
  manifest.frames = fields.integer("frames", 0);
  manifest.hash = fields.text("hash");
  manifest.exitCode = fields.integer("exit_code", -1);
  manifest.error = fields.text("error");
  manifest.stats = fields.object("stats");
  manifest.seconds = fields.number("seconds", 0.0);
  manifest.host = fields.text("host");
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
