#include "scene_input/VariantsFile.h"

#include "scene/InputError.h"

#include <cctype>
#include <cmath>
#include <fstream>
#include <set>
#include <sstream>

namespace ivshadow {
namespace {

std::string trim(const std::string& text) {
  const auto first = text.find_first_not_of(" \t\r");
  if (first == std::string::npos) return {};
  const auto last = text.find_last_not_of(" \t\r");
  return text.substr(first, last - first + 1);
}

// File names and HTML ids: letters, digits, '-', '_' and '.'; anything else becomes '_'.
std::string sanitise(const std::string& text) {
  std::string out;
  for (char c : text)
    out +=
        (std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == '.') ? c : '_';
  while (out.find("__") != std::string::npos) out.replace(out.find("__"), 2, "_");
  if (!out.empty() && out.back() == '_') out.pop_back();
  return out;
}

[[noreturn]] void fail(const std::string& path, int line, const std::string& what) {
  throw InputError(path + ":" + std::to_string(line) + ": error: " + what);
}

// "NODE.field = VALUE" -> "NODE.field=VALUE", checked for shape only.
std::string assignment(const std::string& text, const std::string& path, int line) {
  const auto equals = text.find('=');
  if (equals == std::string::npos)
    fail(path, line, "expected NODE.field = VALUE, found \"" + text + "\"");
  const std::string target = trim(text.substr(0, equals));
  const std::string value = trim(text.substr(equals + 1));
  const auto dot = target.find('.');
  if (dot == std::string::npos || dot == 0 || dot + 1 == target.size() ||
      target.find_first_of(" \t") != std::string::npos)
    fail(path, line, "expected NODE.field before '=', found \"" + target + "\"");
  if (value.empty()) fail(path, line, "no value after '=' for " + target);
  return target + "=" + value;
}

// The most variants a file (a range, or a crossed sweep) may make.
constexpr std::size_t kMaxVariants = 10000;

std::vector<std::string> sweepValues(const std::string& values, const std::string& path, int line) {
  std::vector<std::string> out;
  const auto range = values.find("..");
  if (range != std::string::npos && values.find('|') == std::string::npos) {
    std::istringstream in(values.substr(0, range) + " " + values.substr(range + 2));
    double from = 0, to = 0, step = 0;
    std::string word;
    if (!(in >> from >> to >> word >> step) || word != "step" || !(step > 0.0) ||
        !std::isfinite(from) || !std::isfinite(to))
      fail(path, line, "expected a range A .. B step S with S > 0, found \"" + values + "\"");
    const double count = std::floor((to - from) / step + 1e-9) + 1.0;
    if (!(count >= 1.0 && count <= double(kMaxVariants))) {
      // Printed as a double: a range of 1e300 values has no integer type to convert to
      // (VariantsFileFuzzer found the conversion's undefined behaviour).
      std::ostringstream given;
      given << count;
      fail(path, line,
           "the range gives " + given.str() + " values; expected 1 to " +
               std::to_string(kMaxVariants));
    }
    for (long i = 0; i < long(count); ++i) {
      std::ostringstream value;
      value << from + double(i) * step;
      out.push_back(value.str());
    }
    return out;
  }
  std::istringstream in(values);
  std::string value;
  while (std::getline(in, value, '|')) {
    value = trim(value);
    if (value.empty()) fail(path, line, "an empty value in the list \"" + values + "\"");
    out.push_back(value);
  }
  return out;
}

// "A * B * C": the factors of a crossed sweep, split at each '*' outside double quotes (an
// Inventor string value may hold one).
std::vector<std::string> factors(const std::string& text) {
  std::vector<std::string> out(1);
  bool quoted = false;
  for (char c : text) {
    if (c == '"') quoted = !quoted;
    if (c == '*' && !quoted)
      out.emplace_back();
    else
      out.back() += c;
  }
  return out;
}

// The variants of "sweep NAME NODE.field = VALUES [* NODE.field = VALUES ...]": one per
// combination of values, the first factor varying slowest, named NAME-V1-V2-...
std::vector<Variant> crossedSweep(const std::string& name, const std::string& rest,
                                  const std::string& path, int line) {
  std::vector<Variant> out{{name, line, {}}};
  for (const std::string& factor : factors(rest)) {
    const std::string swept = assignment(trim(factor), path, line);
    const auto equals = swept.find('=');
    const std::string target = swept.substr(0, equals);
    const std::vector<std::string> values = sweepValues(swept.substr(equals + 1), path, line);
    if (out.size() * values.size() > kMaxVariants)
      fail(path, line,
           "the crossed sweep gives more than " + std::to_string(kMaxVariants) + " variants");
    std::vector<Variant> crossed;
    for (const Variant& partial : out)
      for (const std::string& value : values) {
        Variant variant = partial;
        variant.name += "-" + value;
        variant.assignments.push_back({target + "=" + value, line});
        crossed.push_back(std::move(variant));
      }
    out = std::move(crossed);
  }
  for (Variant& variant : out) variant.name = sanitise(variant.name);
  return out;
}

}  // namespace

std::vector<Variant> parseVariants(const std::string& text, const std::string& path) {
  std::vector<Variant> variants;
  // Variants that the current block's shared assignment lines go to.
  std::size_t blockStart = 0;
  bool inBlock = false;
  std::istringstream in(text);
  std::string raw;
  int line = 0;
  while (std::getline(in, raw)) {
    ++line;
    const std::string content = trim(raw.substr(0, raw.find('#')));
    if (content.empty()) continue;
    std::istringstream words(content);
    std::string keyword, name;
    words >> keyword;
    if (keyword == "variant") {
      if (!(words >> name) || !words.eof())
        fail(path, line, "expected \"variant NAME\" with a name without spaces");
      blockStart = variants.size();
      if (sanitise(name).empty())
        fail(path, line,
             "variant name \"" + name +
                 "\" keeps no character in a file name (letters A-Z and a-z, digits, '-', '_' "
                 "and '.' are kept, the rest dropped); name it with some of those");
      variants.push_back({sanitise(name), line, {}});
      inBlock = true;
    } else if (keyword == "sweep") {
      if (!(words >> name)) fail(path, line, "expected \"sweep NAME NODE.field = VALUES\"");
      std::string rest;
      std::getline(words, rest);
      blockStart = variants.size();
      for (Variant& variant : crossedSweep(name, rest, path, line))
        variants.push_back(std::move(variant));
      inBlock = true;
    } else if (inBlock) {
      const std::string text = assignment(content, path, line);
      for (std::size_t i = blockStart; i < variants.size(); ++i)
        variants[i].assignments.push_back({text, line});
    } else {
      fail(path, line, "expected \"variant NAME\" or \"sweep NAME ...\" before assignments");
    }
  }
  if (variants.empty()) fail(path, line, "no variants (expected \"variant NAME\" or \"sweep\")");
  std::set<std::string> names;
  for (const Variant& variant : variants) {
    if (!names.insert(variant.name).second)
      fail(path, variant.line, "a second variant named \"" + variant.name + "\"");
    // A variant's name names its output files (NAME.png, NAME.log and their temporary names),
    // which file systems limit to 255 bytes.
    if (variant.name.size() > kMaxVariantName)
      fail(path, variant.line,
           "variant name of " + std::to_string(variant.name.size()) + " characters; at most " +
               std::to_string(kMaxVariantName) + ", since it names the output files");
    // The sweep's own files share the variants' directories (docs/VARIANTS.md): its list of
    // variants is manifests/plan.json beside their NAME.json (compared without case, for
    // file systems that ignore it), and its scratch files and temporaries are hidden ones
    // beginning ".NAME.", which a hidden variant's picture could match and lose.
    std::string lower = variant.name;
    for (char& c : lower) c = char(std::tolower(static_cast<unsigned char>(c)));
    if (lower == "plan")
      fail(path, variant.line,
           "variant name \"" + variant.name +
               "\" is taken by the sweep's own manifests/plan.json; choose another");
    if (!variant.name.empty() && variant.name[0] == '.')
      fail(path, variant.line,
           "variant name \"" + variant.name +
               "\" begins with '.', as the sweep's scratch files do; choose another");
  }
  return variants;
}

std::vector<Variant> readVariantsFile(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(path + ": error: cannot open the variants file");
  std::stringstream text;
  text << in.rdbuf();
  return parseVariants(text.str(), path);
}

}  // namespace ivshadow
