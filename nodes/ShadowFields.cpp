#include "nodes/ShadowFields.h"

#include <Inventor/fields/SoFieldData.h>
#include <Inventor/fields/SoSFEnum.h>
#include <Inventor/fields/SoSFFloat.h>
#include <Inventor/fields/SoSFInt32.h>

namespace ivshadow {
namespace {

void addToNode(SoFieldContainer* node, SoFieldData* fieldData, SoField& field, ShadowFieldId id) {
  field.setContainer(node);
  fieldData->addField(node, shadowField(id).name, &field);
}

}  // namespace

void addShadowField(SoFieldContainer* node, SoFieldData* fieldData, bool firstInstance,
                    SoSFEnum& field, ShadowFieldId id) {
  const ShadowFieldSpec& spec = shadowField(id);
  field.setValue(int(spec.defaultValue));
  addToNode(node, fieldData, field, id);
  const EnumNames& names = spec.enumNames;
  if (firstInstance)
    for (std::size_t value = 0; value < names.count; ++value)
      fieldData->addEnumValue(names.type, names.names[value], int(value));
  int count = 0;
  const int* values = nullptr;
  const SbName* valueNames = nullptr;
  fieldData->getEnumData(names.type, count, values, valueNames);
  field.setEnums(count, values, valueNames);
}

void addShadowField(SoFieldContainer* node, SoFieldData* fieldData, bool, SoSFInt32& field,
                    ShadowFieldId id) {
  field.setValue(int(shadowField(id).defaultValue));
  addToNode(node, fieldData, field, id);
}

void addShadowField(SoFieldContainer* node, SoFieldData* fieldData, bool, SoSFFloat& field,
                    ShadowFieldId id) {
  field.setValue(float(shadowField(id).defaultValue));
  addToNode(node, fieldData, field, id);
}

}  // namespace ivshadow
