#include "scene_input/FieldAssignment.h"

#include "scene/InputError.h"
#include "scene_input/CoinMessageCapture.h"

#include <Inventor/SoInput.h>
#include <Inventor/SoPath.h>
#include <Inventor/actions/SoSearchAction.h>
#include <Inventor/fields/SoField.h>
#include <Inventor/fields/SoMFBitMask.h>
#include <Inventor/fields/SoMFEnum.h>
#include <Inventor/fields/SoSFBitMask.h>
#include <Inventor/fields/SoSFEnum.h>
#include <Inventor/lists/SoFieldList.h>
#include <Inventor/lists/SoPathList.h>
#include <Inventor/nodes/SoNode.h>

#include <set>
#include <vector>

namespace ivshadow {
namespace {

std::string joined(const std::set<std::string>& names) {
  std::string out;
  for (const std::string& name : names) out += (out.empty() ? "" : ", ") + name;
  return out.empty() ? "(none)" : out;
}

std::vector<SoNode*> nodesNamed(SoNode* root, const std::string& name) {
  SoSearchAction search;
  search.setName(SbName(name.c_str()));
  search.setInterest(SoSearchAction::ALL);
  search.setSearchingAll(TRUE);
  search.apply(root);
  std::vector<SoNode*> nodes;
  const SoPathList& paths = search.getPaths();
  for (int i = 0; i < paths.getLength(); ++i) nodes.push_back(paths[i]->getTail());
  return nodes;
}

std::set<std::string> namesInScene(SoNode* root) {
  SoSearchAction search;
  search.setType(SoNode::getClassTypeId());
  search.setInterest(SoSearchAction::ALL);
  search.setSearchingAll(TRUE);
  search.apply(root);
  std::set<std::string> names;
  const SoPathList& paths = search.getPaths();
  for (int i = 0; i < paths.getLength(); ++i) {
    const SbName name = paths[i]->getTail()->getName();
    if (name.getLength() > 0) names.insert(name.getString());
  }
  return names;
}

std::set<std::string> fieldNames(const SoNode* node) {
  SoFieldList fields;
  node->getFields(fields);
  std::set<std::string> names;
  for (int i = 0; i < fields.getLength(); ++i) {
    SbName name;
    node->getFieldName(fields[i], name);
    names.insert(name.getString());
  }
  return names;
}

// The names an enum or bit mask field accepts, in the order its node defines them, as Coin
// holds them for the field: the node's own table, so no list is kept here.
template <typename EnumField>
std::string enumNames(const EnumField& field) {
  std::string names;
  for (int i = 0; i < field.getNumEnums(); ++i) {
    SbName name;
    field.getEnum(i, name);
    names += (names.empty() ? "" : ", ") + std::string(name.getString());
  }
  return names;
}

// What the value of an enum or bit mask field must be; empty for fields of other types.
std::string expectedEnum(const SoField& field) {
  const SoType type = field.getTypeId();
  if (type.isDerivedFrom(SoSFBitMask::getClassTypeId()) ||
      type.isDerivedFrom(SoMFBitMask::getClassTypeId())) {
    const std::string names = type.isDerivedFrom(SoSFBitMask::getClassTypeId())
                                  ? enumNames(static_cast<const SoSFBitMask&>(field))
                                  : enumNames(static_cast<const SoMFBitMask&>(field));
    return "; expected one or more of " + names + ", joined by | in parentheses: (A | B)";
  }
  if (type.isDerivedFrom(SoSFEnum::getClassTypeId()))
    return "; expected one of " + enumNames(static_cast<const SoSFEnum&>(field));
  if (type.isDerivedFrom(SoMFEnum::getClassTypeId()))
    return "; expected one of " + enumNames(static_cast<const SoMFEnum&>(field));
  return {};
}

}  // namespace

FieldAssignment FieldAssignment::parse(const std::string& text) {
  const std::size_t equals = text.find('=');
  const std::size_t dot = text.find('.');
  if (equals == std::string::npos || dot == std::string::npos || dot > equals || dot == 0 ||
      dot + 1 == equals) {
    throw InputError("--set '" + text +
                     "': error: expected NAME.field=VALUE, e.g. Glass.transparency=0.5");
  }
  FieldAssignment assignment;
  assignment.text = text;
  assignment.node = text.substr(0, dot);
  assignment.field = text.substr(dot + 1, equals - dot - 1);
  assignment.value = text.substr(equals + 1);
  return assignment;
}

void FieldAssignment::apply(SoNode* root, const std::string& sceneName) const {
  const std::string where = "--set '" + text + "': error: ";
  const std::vector<SoNode*> nodes = nodesNamed(root, node);
  if (nodes.empty()) {
    throw InputError(where + "no node named '" + node + "' in " + sceneName +
                     " (DEF names there: " + joined(namesInScene(root)) + ")");
  }
  for (SoNode* target : nodes) {
    SoField* fieldPtr = target->getField(SbName(field.c_str()));
    if (fieldPtr == nullptr) {
      throw InputError(where + "node '" + node + "' (" + target->getTypeId().getName().getString() +
                       ") has no field '" + field + "' (its fields: " + joined(fieldNames(target)) +
                       ")");
    }
    // SoField::set reads what it can and ignores the rest ("1e12" as an SFInt32 gives 1, "0 0
    // 4 garbage" as an SFVec3f drops the garbage), where a file with the same text fails to
    // read. Reading through an SoInput first shows whether anything is left over.
    CoinMessageCapture capture;
    SbString previous;
    fieldPtr->get(previous);
    SoInput input;
    input.setBuffer(value.data(), value.size());
    const bool parsed = fieldPtr->read(&input, SbName(field.c_str()));
    SbString rest;
    const bool leftOver = parsed && input.read(rest);
    // Coin replaces a number it cannot hold (1e39 as a float) by 0 with a read error and
    // reads on; the same value in a file is refused.
    const bool replaced = parsed && !capture.firstError().text.empty();
    if (!parsed || leftOver || replaced || !fieldPtr->set(value.c_str())) {
      fieldPtr->set(previous.getString());
      const std::string detail = leftOver
                                     ? "'" + std::string(rest.getString()) + "' follows the value"
                                     : capture.firstError().text;
      throw InputError(where + "cannot parse '" + value + "' as " +
                       fieldPtr->getTypeId().getName().getString() + " for " + node + "." + field +
                       (detail.empty() ? "" : " (" + detail + ")") + expectedEnum(*fieldPtr));
    }
  }
}

}  // namespace ivshadow
