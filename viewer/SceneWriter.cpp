#include "viewer/SceneWriter.h"

#include "image/AtomicFile.h"
#include "scene/InputError.h"

#include <Inventor/SoOutput.h>
#include <Inventor/actions/SoWriteAction.h>
#include <Inventor/nodes/SoNode.h>

namespace ivshadow {

void writeScene(SoNode* root, const std::string& path) {
  AtomicFile::checkWritable(path, "the scene");
  AtomicFile file(path);
  SoOutput output;
  if (!output.openFile(file.temporaryPath().c_str())) {
    throw InputError(path + ": error: cannot open for writing");
  }
  SoWriteAction write(&output);
  write.apply(root);
  output.closeFile();
  try {
    file.commit();
  } catch (const std::exception& error) {
    throw InputError(path + ": error: " + error.what());
  }
}

}  // namespace ivshadow
