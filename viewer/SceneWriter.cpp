#include "viewer/SceneWriter.h"

#include "image_files/AtomicFile.h"
#include "scene/InputError.h"

#include <Inventor/SoOutput.h>
#include <Inventor/actions/SoWriteAction.h>
#include <Inventor/nodes/SoNode.h>

namespace ivshadow {

void writeScene(SoNode* root, const std::string& path) {
  AtomicFile::checkWritable(path, "the scene");
  AtomicFile file(path);
  writeSceneTo(root, file.temporaryPath(), path);
  try {
    file.commit();
  } catch (const std::exception& error) {
    throw InputError(path + ": error: " + error.what());
  }
}

void writeSceneTo(SoNode* root, const std::string& file, const std::string& name) {
  SoOutput output;
  if (!output.openFile(file.c_str())) throw InputError(name + ": error: cannot open for writing");
  SoWriteAction write(&output);
  write.apply(root);
  output.closeFile();
}

}  // namespace ivshadow
