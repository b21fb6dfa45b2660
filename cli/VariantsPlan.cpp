#include "cli/VariantsPlan.h"

#include "cli/JsonFields.h"
#include "image_files/AtomicFile.h"
#include "scene/InputError.h"

#include <nlohmann/json.hpp>

#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>

namespace ivshadow {
namespace {

// FNV-1a: the same on every machine and compiler, unlike std::hash, which matters because the
// shards of one sweep may run on different nodes.
class Fnv1a {
 public:
  void add(const std::string& text) {
    for (unsigned char c : text) value_ = (value_ ^ c) * 1099511628211ull;
    // A separator, so that ("ab", "c") and ("a", "bc") hash differently.
    value_ = (value_ ^ 0xffu) * 1099511628211ull;
  }
  std::string hex() const {
    char text[17];
    std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(value_));
    return text;
  }

 private:
  std::uint64_t value_ = 14695981039346656037ull;
};

std::string fileBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": error: cannot read the file");
  return std::string(std::istreambuf_iterator<char>(in), {});
}

}  // namespace

VariantsPlan VariantsPlan::make(const std::string& base, const std::string& variantsFile,
                                const std::string& size, int frames,
                                std::vector<Variant> variants) {
  VariantsPlan plan;
  plan.base = base;
  plan.variantsFile = variantsFile;
  plan.size = size;
  plan.frames = frames;
  plan.variants = std::move(variants);
  const std::string scene = fileBytes(base);
  for (const Variant& variant : plan.variants) {
    Fnv1a hash;
    hash.add(scene);
    hash.add(size);
    hash.add(std::to_string(frames));
    hash.add(variant.name);
    for (const Variant::Assignment& assignment : variant.assignments) hash.add(assignment.text);
    plan.hashes.push_back(hash.hex());
  }
  return plan;
}

std::string VariantsPlan::path(const std::string& outputDir) {
  return outputDir + "/manifests/plan.json";
}

VariantsPlan VariantsPlan::read(const std::string& outputDir) {
  const std::string file = path(outputDir);
  std::error_code ec;
  if (!std::filesystem::exists(file, ec))
    throw InputError(file + ": error: no plan of a sweep here; run `ivshadow variants ... -o " +
                     outputDir + "` (with or without --shard) first");
  const nlohmann::json json = readJsonObject(file, "the plan of the sweep");
  if (!json.contains("variants") || !json["variants"].is_array())
    throw InputError(file +
                     ": error: not a plan of a sweep (expected a JSON object with "
                     "\"variants\")");
  VariantsPlan plan;
  try {
    plan.base = json.at("base").get<std::string>();
    plan.variantsFile = json.at("variants_file").get<std::string>();
    plan.size = json.at("size").get<std::string>();
    plan.frames = json.at("frames").get<int>();
    for (const nlohmann::json& entry : json["variants"]) {
      Variant variant;
      variant.name = entry.at("name").get<std::string>();
      variant.line = entry.at("line").get<int>();
      for (const nlohmann::json& assignment : entry.at("assignments"))
        variant.assignments.push_back(
            {assignment.at("text").get<std::string>(), assignment.at("line").get<int>()});
      plan.variants.push_back(std::move(variant));
      plan.hashes.push_back(entry.at("hash").get<std::string>());
    }
  } catch (const nlohmann::json::exception& error) {
    // nlohmann's message without its "[json.exception.type_error.302] " prefix.
    std::string message = error.what();
    if (message.find("] ") != std::string::npos) message = message.substr(message.find("] ") + 2);
    throw InputError(file +
                     ": error: not a plan of a sweep: a field of the wrong type or missing (" +
                     message + ")");
  }
  return plan;
}

void VariantsPlan::write(const std::string& outputDir) const {
  nlohmann::json entries = nlohmann::json::array();
  for (std::size_t i = 0; i < variants.size(); ++i) {
    nlohmann::json assignments = nlohmann::json::array();
    for (const Variant::Assignment& assignment : variants[i].assignments)
      assignments.push_back({{"text", assignment.text}, {"line", assignment.line}});
    entries.push_back({{"name", variants[i].name},
                       {"line", variants[i].line},
                       {"assignments", assignments},
                       {"hash", hashes[i]}});
  }
  const nlohmann::json json = {{"base", base},
                               {"variants_file", variantsFile},
                               {"size", size},
                               {"frames", frames},
                               {"variants", entries}};
  writeTextFileAtomically(path(outputDir), json.dump(2) + "\n");
}

}  // namespace ivshadow
