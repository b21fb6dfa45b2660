#pragma once

// The shadow fields that SoDeepShadowLight, SoDeepShadowSpotLight, SoDeepShadowDirectionalLight
// and SoTransparentShadowGroup share (the group's cast the shadows of its ordinary lights), as
// Coin's SoShadowStyle serves several lights: FIELD(field type, name) for each, in the order the
// nodes add them and files write them. The node classes declare them from this one list; what
// each means, its default and its range are in each node's FILE FORMAT block.
#define IVSHADOW_SHADOW_FIELDS(FIELD) \
  FIELD(SoSFEnum, method)             \
  FIELD(SoSFInt32, resolution)        \
  FIELD(SoSFInt32, maxLayers)         \
  FIELD(SoSFInt32, slices)            \
  FIELD(SoSFFloat, bias)              \
  FIELD(SoSFEnum, shadowColor)        \
  FIELD(SoSFEnum, colorModel)         \
  FIELD(SoSFEnum, precision)          \
  FIELD(SoSFEnum, filter)             \
  FIELD(SoSFInt32, filterSize)        \
  FIELD(SoSFEnum, layerOverflow)

// The distances from the light that a point or spot light's map covers. A directional light's
// map, and those of a group's ordinary lights, are fitted to the casters instead.
#define IVSHADOW_MAP_RANGE_FIELDS(FIELD) \
  FIELD(SoSFFloat, nearRadius)           \
  FIELD(SoSFFloat, farRadius)

// The FIELD that declares each field in a node class's body.
#define IVSHADOW_DECLARE_FIELD(type, name) type name;
