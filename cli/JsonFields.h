#pragma once

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace ivshadow {

// Reads the JSON object of the file `path` (`what` says what it holds, e.g. "the manifest of
// variant a"). Throws InputError naming the file and what is wrong: empty, cut short or not
// JSON (with the line where it stops being JSON), or not an object.
nlohmann::json readJsonObject(const std::string& path, const std::string& what);

// The fields of a JSON object read from `path`, each of the type it must have: a field of
// another type throws InputError naming the file, the field and both types, instead of
// nlohmann's json.exception, which names neither. An absent field gives the fallback.
class JsonFields {
 public:
  JsonFields(const nlohmann::json& object, std::string path)
      : object_(object), path_(std::move(path)) {}

  std::string text(const char* key, const std::string& fallback = {}) const;
  int integer(const char* key, int fallback) const;
  double number(const char* key, double fallback) const;
  std::vector<std::string> texts(const char* key) const;
  // An object, or null when absent or null.
  nlohmann::json object(const char* key) const;

 private:
  const nlohmann::json* field(const char* key, bool (nlohmann::json::*is)() const noexcept,
                              const char* expected) const;

  const nlohmann::json& object_;
  std::string path_;
};

}  // namespace ivshadow
