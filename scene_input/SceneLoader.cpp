#include "scene_input/SceneLoader.h"

#include "scene/InputError.h"
#include "scene/ShapeValidation.h"
#include "scene_input/CoinMessageCapture.h"
#include "scene_input/ForeignNodes.h"
#include "scene_input/SceneFileCheck.h"

#include <Inventor/SoDB.h>
#include <Inventor/SoInput.h>
#include <Inventor/nodes/SoNode.h>
#include <Inventor/nodes/SoSeparator.h>

#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>

namespace ivshadow {

std::string locationPrefix(const std::string& file, int line) {
  return line > 0 ? file + ":" + std::to_string(line) + ": " : file + ": ";
}

namespace {

bool holdsANode(const std::string& path) {
  SoInput input;
  if (!input.openFile(path.c_str(), TRUE)) return false;
  SoNode* node = nullptr;
  const bool read = SoDB::read(&input, node);
  if (node != nullptr) {
    node->ref();
    node->unref();
  }
  return read && node != nullptr;
}

}  // namespace

LoadedScene loadScene(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (!fs::exists(status)) {
    throw InputError(path + ": error: no such file (expected an Open Inventor .iv file)");
  }
  if (fs::is_directory(status)) {
    throw InputError(path + ": error: is a directory (expected an Open Inventor .iv file)");
  }
  if (std::string kind = notRegularFile(status); !kind.empty())
    throw InputError(path + ": error: " + kind + " (expected an Open Inventor .iv file)");
  if (::access(path.c_str(), R_OK) != 0) {
    throw InputError(path + ": error: cannot read: " + std::strerror(errno));
  }

  checkSceneFile(path);
  registerForeignNodes();
  CoinMessageCapture capture;
  SoInput input;
  if (!input.openFile(path.c_str(), TRUE)) {
    throw InputError(path + ": error: cannot open: " + capture.firstError().text);
  }
  if (!input.isValidFile()) {
    throw InputError(path +
                     ": error: not an Open Inventor or VRML file (expected a header such as "
                     "'#Inventor V2.1 ascii' on line 1)");
  }
  SoSeparator* root = SoDB::readAll(&input);
  LoadedScene scene;
  scene.root = CoinRef<SoSeparator>(root);
  const CoinMessageCapture::Message error = capture.firstError();
  if (root == nullptr || !error.text.empty()) {
    const std::string text = error.text.empty() ? "could not be read" : error.text;
    throw InputError(locationPrefix(path, error.line) + "error: " + text);
  }
  // SoDB::readAll returns a file's only top-level Separator itself, so an empty root is
  // either `Separator { }` (an empty scene, rendered empty) or a file without any node (most
  // likely not the file meant, refused). Reading the first node again tells them apart.
  if (root->getNumChildren() == 0 && !holdsANode(path)) {
    throw InputError(path +
                     ": error: the file holds no nodes (expected at least one node "
                     "after the header)");
  }
  for (const CoinMessageCapture::Message& message : capture.messages()) {
    scene.warnings.push_back(locationPrefix(path, message.line) + "warning: " + message.text);
  }
  for (std::string& warning : unknownNodeWarnings(root, path))
    scene.warnings.push_back(std::move(warning));
  for (std::string& warning : removeDefectiveShapes(root, path))
    scene.warnings.push_back(std::move(warning));
  return scene;
}

}  // namespace ivshadow
