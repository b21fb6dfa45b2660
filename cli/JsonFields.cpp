#include "cli/JsonFields.h"

#include "scene/InputError.h"

#include <fstream>
#include <iterator>

namespace ivshadow {
namespace {

// "a string", "an array", "null": nlohmann's type name as a message says it.
std::string typeOf(const nlohmann::json& value) {
  const std::string name = value.type_name();
  if (value.is_null()) return name;
  return (name.find_first_of("aeiou") == 0 ? "an " : "a ") + name;
}

}  // namespace

nlohmann::json readJsonObject(const std::string& path, const std::string& what) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": error: cannot read " + what);
  const std::string text((std::istreambuf_iterator<char>(in)), {});
  if (text.find_first_not_of(" \t\r\n") == std::string::npos)
    throw InputError(path + ": error: " + what + " is empty (cut short while it was written?)");
  nlohmann::json json;
  try {
    json = nlohmann::json::parse(text);
  } catch (const nlohmann::json::parse_error& error) {
    // nlohmann's message after its "[json.exception.parse_error.101] " prefix says where.
    std::string message = error.what();
    if (message.rfind("[json.exception", 0) == 0 && message.find("] ") != std::string::npos)
      message = message.substr(message.find("] ") + 2);
    throw InputError(path + ": error: " + what + " is not valid JSON (cut short?): " + message);
  }
  if (!json.is_object())
    throw InputError(path + ": error: " + what + " must be a JSON object; found " + typeOf(json));
  return json;
}

const nlohmann::json* JsonFields::field(const char* key,
                                        bool (nlohmann::json::*is)() const noexcept,
                                        const char* expected) const {
  const auto found = object_.find(key);
  if (found == object_.end()) return nullptr;
  if (!((*found).*is)())
    throw InputError(path_ + ": error: field \"" + key + "\" is " + typeOf(*found) + "; expected " +
                     expected);
  return &*found;
}

std::string JsonFields::text(const char* key, const std::string& fallback) const {
  const nlohmann::json* value = field(key, &nlohmann::json::is_string, "a string");
  return value ? value->get<std::string>() : fallback;
}

int JsonFields::integer(const char* key, int fallback) const {
  const nlohmann::json* value = field(key, &nlohmann::json::is_number_integer, "a whole number");
  return value ? value->get<int>() : fallback;
}

double JsonFields::number(const char* key, double fallback) const {
  const nlohmann::json* value = field(key, &nlohmann::json::is_number, "a number");
  return value ? value->get<double>() : fallback;
}

nlohmann::json JsonFields::object(const char* key) const {
  // A failed render's statistics are written as null.
  if (object_.contains(key) && object_[key].is_null()) return nlohmann::json();
  const nlohmann::json* value = field(key, &nlohmann::json::is_object, "an object");
  return value ? *value : nlohmann::json();
}

std::vector<std::string> JsonFields::texts(const char* key) const {
  const nlohmann::json* value = field(key, &nlohmann::json::is_array, "an array of strings");
  std::vector<std::string> out;
  if (value == nullptr) return out;
  for (const nlohmann::json& entry : *value) {
    if (!entry.is_string())
      throw InputError(path_ + ": error: field \"" + key + "\" holds " + typeOf(entry) +
                       "; expected strings only");
    out.push_back(entry.get<std::string>());
  }
  return out;
}

}  // namespace ivshadow
