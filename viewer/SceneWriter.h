#pragma once

#include <string>

class SoNode;

namespace ivshadow {

// Writes `root` as an ASCII Inventor file with its current field values, through an
// AtomicFile: a failure leaves no file. Throws InputError naming `path` when it cannot be
// created or written.
void writeScene(SoNode* root, const std::string& path);
// Writes `root` to `file` as it is (a temporary of OutputFiles); errors name `name`.
void writeSceneTo(SoNode* root, const std::string& file, const std::string& name);

}  // namespace ivshadow
