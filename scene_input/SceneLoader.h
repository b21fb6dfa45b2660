#pragma once

#include "scene/CoinRef.h"

#include <string>
#include <vector>

class SoSeparator;

namespace ivshadow {

// A scene read from an .iv (or VRML) file, with the warnings Coin posted while reading it.
struct LoadedScene {
  CoinRef<SoSeparator> root;
  std::vector<std::string> warnings;  // "FILE:LINE: warning: ..." lines
};

// Reads a whole scene file. Throws InputError naming the file and line for a missing,
// unreadable or malformed file (syntax errors, unknown nodes or fields, bad values) or one
// without any node; an empty `Separator { }` is an empty scene, not an error.
LoadedScene loadScene(const std::string& path);

// Formats a location prefix the way compilers do: "FILE:LINE: " or "FILE: ".
std::string locationPrefix(const std::string& file, int line);

}  // namespace ivshadow
