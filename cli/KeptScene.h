#pragma once

#include "cli/RenderCommand.h"
#include "scene/CoinRef.h"
#include "scene_input/FieldAssignment.h"
#include "scene_input/SceneLoader.h"

#include <Inventor/SbName.h>
#include <Inventor/SbString.h>
#include <Inventor/nodes/SoNode.h>

#include <sys/stat.h>

#include <memory>
#include <optional>
#include <string>
#include <vector>

class SoField;

namespace ivshadow {

// A scene a RenderSession keeps from one render to the next, with what its nodes made of it
// (a traced group's extracted scene and the surfaces its camera rays met): the next render of
// the same file, unchanged on disk, at the same size and transparency puts back the fields
// the last one assigned and applies its own, rather than reading the file again.
class KeptScene {
 public:
  // What tells one state of a scene file from another: a file rewritten in place changes its
  // modification time or its size; one replaced by another, its inode.
  struct FileState {
    dev_t device = 0;
    ino_t inode = 0;
    off_t size = 0;
    timespec modified{};
    bool operator==(const FileState& other) const;
  };
  // Nothing when the file cannot be examined (the read that follows says why).
  static std::optional<FileState> stateOf(const std::string& path);

  KeptScene(LoadedScene scene, const RenderOptions& options, const FileState& file);
  ~KeptScene();
  KeptScene(const KeptScene&) = delete;
  KeptScene& operator=(const KeptScene&) = delete;

  // Whether a render of `options` may use this scene: the same file in the same state, the
  // same size and transparency type.
  bool serves(const RenderOptions& options, const FileState& file) const;

  // Puts back the values the fields assigned since the scene was read had in the file; false
  // when one of them cannot be had again to the bit from its text (the scene must then be
  // read afresh).
  bool restore();
  // Saves the value of every field `assignments` name, before they are applied, unless it was
  // saved before; names or fields that are not there are the assignment's to report.
  void remember(const std::vector<FieldAssignment>& assignments);
  // Whether a field was assigned since the scene was read or restored.
  bool assigned() const { return !saved_.empty(); }

  LoadedScene& scene() { return scene_; }

 private:
  struct SavedField;
  LoadedScene scene_;
  std::string path_;
  std::string size_;
  std::string transparency_;
  FileState file_;
  std::vector<SavedField> saved_;
};

}  // namespace ivshadow
