#include "scene_input/ForeignNodes.h"

#include <Inventor/SoDB.h>
#include <Inventor/SoOutput.h>
#include <Inventor/SoPath.h>
#include <Inventor/SoType.h>
#include <Inventor/actions/SoSearchAction.h>
#include <Inventor/actions/SoWriteAction.h>
#include <Inventor/fields/SoField.h>
#include <Inventor/fields/SoFieldData.h>
#include <Inventor/lists/SoPathList.h>
#include <Inventor/nodes/SoGroup.h>
#include <Inventor/nodes/SoIndexedFaceSet.h>
#include <Inventor/nodes/SoIndexedLineSet.h>
#include <Inventor/nodes/SoPointSet.h>
#include <Inventor/nodes/SoSeparator.h>

#include <array>
#include <cstdlib>
#include <set>
#include <sstream>
#include <utility>

namespace ivshadow {
namespace {

// A node of a foreign type read as its Coin base class `Base`. Its field data is its own, as
// Coin's unknown nodes' is: the fields a file declares beyond Base's are added to it, which in
// a class's shared field data would hold offsets valid for the instance that read them alone.
template <class Base>
class ForeignNode : public Base {
 public:
  explicit ForeignNode(SoType type) : type_(type), fields_(Base::getFieldData()) {
    baseFields_ = fields_.getNumFields();
    // Written back with its fields declared, as FreeCAD writes it: a reader without the type
    // (plain Coin, or this reader) needs the declaration for the fields Base does not have.
    this->isBuiltIn = FALSE;
  }

  SoType getTypeId() const override { return type_; }

 protected:
  const SoFieldData* getFieldData() const override { return &fields_; }
  ~ForeignNode() override {
    // The fields the file declared were made for this node (SoFieldData::readFieldDescriptions).
    for (int i = fields_.getNumFields() - 1; i >= baseFields_; --i)
      delete fields_.getField(this, i);
  }

 private:
  SoType type_;
  SoFieldData fields_;
  int baseFields_ = 0;
};

template <class Base>
SoNode* make(SoType type) {
  return new ForeignNode<Base>(type);
}

struct Foreign {
  const char* name;
  SoType (*base)();
  SoNode* (*make)(SoType);
};

// FreeCAD's (0.20) groups and shapes, by the Coin class each derives from.
constexpr std::array<Foreign, 10> kForeign{{
    {"SoFCSelectionRoot", &SoSeparator::getClassTypeId, &make<SoSeparator>},
    {"SoFCUnifiedSelection", &SoSeparator::getClassTypeId, &make<SoSeparator>},
    {"SoFCSeparator", &SoSeparator::getClassTypeId, &make<SoSeparator>},
    {"SoFCPathAnnotation", &SoSeparator::getClassTypeId, &make<SoSeparator>},
    {"SoFCSelection", &SoGroup::getClassTypeId, &make<SoGroup>},
    {"SoSkipBoundingGroup", &SoGroup::getClassTypeId, &make<SoGroup>},
    {"SoBrepFaceSet", &SoIndexedFaceSet::getClassTypeId, &make<SoIndexedFaceSet>},
    {"SoFCIndexedFaceSet", &SoIndexedFaceSet::getClassTypeId, &make<SoIndexedFaceSet>},
    {"SoBrepEdgeSet", &SoIndexedLineSet::getClassTypeId, &make<SoIndexedLineSet>},
    {"SoBrepPointSet", &SoPointSet::getClassTypeId, &make<SoPointSet>},
}};

std::array<SoType, kForeign.size()> types;

// SoNode's counter of action method indices is protected: a class derived from it reads it.
struct NodeIndex : SoNode {
  static int next() {
    const int index = getNextActionMethodIndex();
    incNextActionMethodIndex();
    return index;
  }
};

template <std::size_t I>
void* create() {
  return kForeign[I].make(types[I]);
}

template <std::size_t... I>
void registerAll(std::index_sequence<I...>) {
  constexpr SoType::instantiationMethod creators[] = {&create<I>...};
  for (std::size_t i = 0; i < kForeign.size(); ++i) {
    if (!SoType::fromName(kForeign[i].name).isBad()) continue;
    // As SO_NODE_INIT_CLASS registers a node class: its own index into the actions' method
    // tables, which take the base class's methods for it.
    types[i] = SoType::createType(kForeign[i].base(), kForeign[i].name, creators[i],
                                  uint16_t(NodeIndex::next()));
  }
}

// The name a node writes itself under (an unknown node's is the file's; SoBase's accessor of
// it is protected): the first word its write action puts out after a DEF name.
std::string writtenTypeName(SoNode* node) {
  std::string written;
  {
    SoOutput out;
    // Coin grows the buffer with realloc and leaves it to its owner.
    out.setBuffer(std::malloc(1024), 1024, std::realloc);
    out.setHeaderString("");
    SoWriteAction write(&out);
    write.apply(node);
    void* buffer = nullptr;
    std::size_t size = 0;
    out.getBuffer(buffer, size);
    written.assign(static_cast<const char*>(buffer), size);
    std::free(buffer);
  }
  std::istringstream text(written);
  std::string word;
  text >> word;
  if (word == "DEF") text >> word >> word;
  return word;
}

}  // namespace

void registerForeignNodes() {
  static const bool registered = [] {
    SoDB::init();  // a loader may be the first to use Coin; init is idempotent
    registerAll(std::make_index_sequence<kForeign.size()>());
    return true;
  }();
  (void)registered;
}

std::vector<std::string> unknownNodeWarnings(SoNode* root, const std::string& file) {
  std::vector<std::string> warnings;
  const SoType unknown = SoType::fromName("UnknownNode");
  if (unknown.isBad() || root == nullptr) return warnings;
  SoSearchAction search;
  search.setType(unknown);
  search.setInterest(SoSearchAction::ALL);
  search.setSearchingAll(TRUE);
  search.apply(root);
  std::set<std::string> named;
  for (int i = 0; i < search.getPaths().getLength(); ++i) {
    const std::string type = writtenTypeName(search.getPaths()[i]->getTail());
    if (named.insert(type).second)
      warnings.push_back(file + ": warning: node type '" + type +
                         "' is known neither to Coin nor to the plugin: it is not drawn, nor "
                         "anything inside it");
  }
  return warnings;
}

}  // namespace ivshadow
