#pragma once

#include <string>

class SoNode;

namespace ivshadow {

// "NAME.field=VALUE": assigns VALUE, in Inventor field syntax parsed by Coin (SoField::set),
// to the field of every node DEF-named NAME in a scene.
struct FieldAssignment {
  std::string text;  // as the user wrote it, for messages
  std::string node;
  std::string field;
  std::string value;

  // Throws InputError when `text` is not NAME.field=VALUE.
  static FieldAssignment parse(const std::string& text);

  // Throws InputError naming `sceneName` and the node, field or value at fault; lists the
  // names or fields that do exist so the user can correct the spelling.
  void apply(SoNode* root, const std::string& sceneName) const;
};

}  // namespace ivshadow
