#pragma once

#include "ivshadow/ShadowFieldList.h"
#include "nodes/ShadowFieldTable.h"

#include <Inventor/nodes/SoSubNode.h>

class SoFieldContainer;
class SoFieldData;
class SoSFEnum;
class SoSFFloat;
class SoSFInt32;

namespace ivshadow {

// Adds one shadow field to the node being constructed as SO_NODE_ADD_FIELD does, with the
// table's default; an enum field gets its enum's names (SO_NODE_SET_SF_ENUM_TYPE), which the
// class's field data takes on its first instance.
void addShadowField(SoFieldContainer* node, SoFieldData* fieldData, bool firstInstance,
                    SoSFEnum& field, ShadowFieldId id);
void addShadowField(SoFieldContainer* node, SoFieldData* fieldData, bool firstInstance,
                    SoSFInt32& field, ShadowFieldId id);
void addShadowField(SoFieldContainer* node, SoFieldData* fieldData, bool firstInstance,
                    SoSFFloat& field, ShadowFieldId id);

}  // namespace ivshadow

// Macros, because a node's field data and instance count, which Coin's SO_NODE_ADD_FIELD
// reads, are private to the node's class: called in its constructor after
// SO_NODE_CONSTRUCTOR, they add the fields of ivshadow/ShadowFieldList.h's lists.
#define IVSHADOW_ADD_TABLE_FIELD(type, name)                                   \
  ivshadow::addShadowField(this, fieldData, SO_NODE_IS_FIRST_INSTANCE(), name, \
                           ivshadow::ShadowFieldId::name);
#define IVSHADOW_ADD_SHADOW_FIELDS() IVSHADOW_SHADOW_FIELDS(IVSHADOW_ADD_TABLE_FIELD)
#define IVSHADOW_ADD_MAP_RANGE_FIELDS() IVSHADOW_MAP_RANGE_FIELDS(IVSHADOW_ADD_TABLE_FIELD)
