#include "cli/KeptScene.h"

#include <Inventor/SoPath.h>
#include <Inventor/actions/SoSearchAction.h>
#include <Inventor/fields/SoField.h>
#include <Inventor/lists/SoPathList.h>
#include <Inventor/nodes/SoSeparator.h>

#include <algorithm>

namespace ivshadow {

struct KeptScene::SavedField {
  CoinRef<SoNode> node;
  SbName name;
  // The value as Inventor text (SoField::get), put back with SoField::set, and the flags set
  // changes: a field left at its default must read as one again, for the nodes that say a
  // setting the user made does nothing (nodes/IdleFields.h).
  SbString text;
  bool wasDefault = false;
  bool wasIgnored = false;
  // The value itself, to check that the text gave it back to the bit: a float written with
  // fewer digits than it holds would not, and the picture would differ from a fresh read's.
  std::unique_ptr<SoField> exact;
};

bool KeptScene::FileState::operator==(const FileState& other) const {
  return device == other.device && inode == other.inode && size == other.size &&
         modified.tv_sec == other.modified.tv_sec && modified.tv_nsec == other.modified.tv_nsec;
}

std::optional<KeptScene::FileState> KeptScene::stateOf(const std::string& path) {
  struct stat info {};
  if (stat(path.c_str(), &info) != 0) return std::nullopt;
  FileState state;
  state.device = info.st_dev;
  state.inode = info.st_ino;
  state.size = info.st_size;
  state.modified = info.st_mtim;
  return state;
}

KeptScene::KeptScene(LoadedScene scene, const RenderOptions& options, const FileState& file)
    : scene_(std::move(scene)),
      path_(options.scene),
      size_(options.size),
      transparency_(options.transparency),
      file_(file) {}

KeptScene::~KeptScene() = default;

bool KeptScene::serves(const RenderOptions& options, const FileState& file) const {
  return options.scene == path_ && options.size == size_ && options.transparency == transparency_ &&
         file == file_;
}

bool KeptScene::restore() {
  bool exact = true;
  for (auto saved = saved_.begin(); saved != saved_.end(); ++saved) {
    SoField* field = saved->node->getField(saved->name);
    if (field == nullptr) return false;
    field->set(saved->text.getString());
    if (field->isIgnored() != saved->wasIgnored) field->setIgnored(saved->wasIgnored);
    field->setDefault(saved->wasDefault);
    if (!field->isSame(*saved->exact)) exact = false;
  }
  saved_.clear();
  return exact;
}

void KeptScene::remember(const std::vector<FieldAssignment>& assignments) {
  for (const FieldAssignment& assignment : assignments) {
    SoSearchAction search;
    search.setName(SbName(assignment.node.c_str()));
    search.setInterest(SoSearchAction::ALL);
    search.setSearchingAll(TRUE);
    search.apply(scene_.root.get());
    const SoPathList& paths = search.getPaths();
    const SbName name(assignment.field.c_str());
    for (int i = 0; i < paths.getLength(); ++i) {
      SoNode* node = paths[i]->getTail();
      SoField* field = node->getField(name);
      if (field == nullptr) continue;
      const bool known = std::any_of(saved_.begin(), saved_.end(), [&](const SavedField& saved) {
        return saved.node.get() == node && saved.name == name;
      });
      if (known) continue;
      SavedField saved;
      saved.node = CoinRef<SoNode>(node);
      saved.name = name;
      field->get(saved.text);
      saved.wasDefault = field->isDefault();
      saved.wasIgnored = field->isIgnored();
      saved.exact.reset(static_cast<SoField*>(field->getTypeId().createInstance()));
      saved.exact->copyFrom(*field);
      saved_.push_back(std::move(saved));
    }
  }
}

}  // namespace ivshadow
