#include "cli/VariantsReport.h"

#include "image_files/OutputFiles.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iomanip>
#include <sstream>

namespace ivshadow {
namespace {

// "pending" only in a merge of shards some of which have not reported (docs/VARIANTS.md).
const char* statusText(const VariantManifest& outcome) {
  if (outcome.ok()) return "ok";
  return outcome.exitCode == VariantManifest::kPending ? "pending" : "failed";
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
    if (!value->is_object() || !value->contains(inner)) return 0.0;
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
    if (!light.is_object() || !light.contains("method") || !light["method"].is_string()) continue;
    const std::string method = light["method"].get<std::string>();
    methods.map = methods.map || method == "MAP";
    methods.rays = methods.rays || method == "RAYS";
  }
  return methods;
}

// "Lamp:0/2/2/0/0/5" per light that has a map, from the render's statistics.
std::string layersText(const nlohmann::json& stats) {
  std::string text;
  if (!stats.is_object() || !stats.contains("dsm_layers_used")) return text;
  // Statistics of an older or edited manifest may lack fields or hold others: such a light
  // is left out rather than the report failing.
  for (const auto& light : stats["dsm_layers_used"]) {
    if (!light.is_object() || light.value("method", nlohmann::json()) != "MAP" ||
        !light.contains("faces") || !light["faces"].is_array())
      continue;
    const nlohmann::json name = light.value("light", nlohmann::json("light"));
    text +=
        (text.empty() ? "" : " ") + (name.is_string() ? name.get<std::string>() : "light") + ":";
    bool first = true;
    for (const nlohmann::json& used : light["faces"]) {
      text += (first ? "" : "/") + (used.is_number() ? used.dump() : std::string("?"));
      first = false;
    }
  }
  return text;
}

std::string shadowMethod(const nlohmann::json& stats) {
  if (!stats.is_object() || !stats.contains("passes") || !stats["passes"].is_object()) return {};
  const nlohmann::json method = stats["passes"].value("shadow_method", nlohmann::json());
  return method.is_string() ? method.get<std::string>() : std::string();
}

// A CSV number, or an empty field when the column does not apply to this render.
std::string field(bool applies, double value) {
  if (!applies) return {};
  std::ostringstream out;
  out << value;
  return out.str();
}

// A count (bytes): written whole, as 104857600, where a double would print 1.04858e+08 and
// lose the last digits.
std::string countField(bool applies, double value) {
  if (!applies) return {};
  return std::to_string(std::uint64_t(std::llround(std::max(value, 0.0))));
}

std::string csvLine(const Variant& variant, const VariantManifest& outcome,
                    const std::string& image) {
  const bool ok = outcome.ok();
  const nlohmann::json& stats = outcome.stats;
  const Methods used = ok ? methodsOf(stats) : Methods{};
  std::ostringstream csv;
  csv << csvField(variant.name) << ',' << csvField(assignmentsText(variant)) << ','
      << statusText(outcome) << ',' << shadowMethod(stats) << ','
      << field(ok, number(stats, "frame_ms_median")) << ','
      << field(used.map, number(stats, "passes", "dsm_build_ms")) << ','
      << field(used.rays, number(stats, "passes", "rays_ms")) << ','
      << field(used.rays, number(stats, "passes", "bvh_build_ms")) << ','
      << field(ok, number(stats, "passes", "peel_ms")) << ','
      << countField(used.map, number(stats, "dsm_bytes")) << ','
      << countField(used.rays, number(stats, "bvh_bytes")) << ',' << csvField(layersText(stats))
      << ',' << (ok ? csvField(image) : "\"\"") << '\n';
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

}  // namespace

void writeVariantsReports(const std::string& outputDir, const std::string& base,
                          const std::vector<Variant>& variants,
                          const std::vector<VariantManifest>& outcomes) {
  std::ostringstream csv;
  // Columns of a method the variant did not use (a map's for traced lights, the rays' for
  // mapped ones) are left empty rather than 0, which would read as "free".
  csv << "variant,assignments,status,shadow_method,frame_ms_median,dsm_build_ms,rays_ms,"
         "bvh_build_ms,peel_ms,dsm_bytes,bvh_bytes,dsm_layers_used,image\n";
  std::ostringstream html;
  html << "<!DOCTYPE html>\n<html><head><meta charset=\"utf-8\"><title>Variants of "
       << htmlEscape(base) << "</title>\n<style>body{font-family:sans-serif}"
       << "figure{display:inline-block;margin:8px;width:260px;vertical-align:top}"
       << "img{width:256px;border:1px solid #999}figcaption{font-size:12px}"
       << ".failed{color:#a00}.idle{color:#a60}</style></head><body>\n<h1>Variants of "
       << htmlEscape(base) << "</h1>\n";
  for (std::size_t i = 0; i < variants.size(); ++i) {
    const Variant& variant = variants[i];
    const VariantManifest& outcome = outcomes[i];
    const bool ok = outcome.ok();
    const std::string image = variant.name + ".png";
    csv << csvLine(variant, outcome, image);
    html << "<figure id=\"" << htmlEscape(variant.name) << "\">";
    if (ok)
      html << "<a href=\"" << htmlEscape(image) << "\"><img src=\"" << htmlEscape(image)
           << "\" alt=\"" << htmlEscape(variant.name) << "\"></a>";
    html << "<figcaption><b>" << htmlEscape(variant.name) << "</b><br>"
         << htmlEscape(assignmentsText(variant)) << "<br>";
    if (!ok) {
      html << "<span class=\"failed\">" << htmlEscape(outcome.error) << "</span>";
    } else {
      html << htmlEscape(captionFigures(outcome.stats));
      // The settings that did nothing on the path this variant rendered by.
      if (outcome.stats.contains("idle_settings"))
        for (const nlohmann::json& idle : outcome.stats.at("idle_settings"))
          html << "<br><span class=\"idle\">" << htmlEscape(idle.get<std::string>()) << "</span>";
    }
    html << "</figcaption></figure>\n";
  }
  html << "</body></html>\n";
  // Both reports or neither, so that the table and the contact sheet never disagree.
  OutputFiles outputs;
  outputs.addText(outputDir + "/variants.csv", csv.str());
  outputs.addText(outputDir + "/index.html", html.str());
  outputs.commit();
}

}  // namespace ivshadow
