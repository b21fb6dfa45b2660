// Shared by the map build and the lookup, so that both agree on the cube layout and on how
// a surface filters light. Included after the #version line.

// Cube face f looks along kFaceAxis[f]; kFaceRight/kFaceUp span its image plane (the
// IVSHADOW_* defines come from callbacks/ShaderConstants.h).
const vec3 kFaceAxis[6] = IVSHADOW_FACE_AXIS;
const vec3 kFaceRight[6] = IVSHADOW_FACE_RIGHT;
const vec3 kFaceUp[6] = IVSHADOW_FACE_UP;

int cubeFace(vec3 d) {
  vec3 a = abs(d);
  if (a.x >= a.y && a.x >= a.z) return d.x >= 0.0 ? 0 : 1;
  if (a.y >= a.z) return d.y >= 0.0 ? 2 : 3;
  return d.z >= 0.0 ? 4 : 5;
}

// Opacity within half an 8-bit step of 1 counts as opaque (kOpaqueAlpha).
bool isOpaque(float alpha) { return alpha >= IVSHADOW_OPAQUE_ALPHA; }

// Coin may draw a shape differently from pass to pass (immediate mode, then a render cache
// that splits its polygons differently), which moves depth by a few ulps: window depths that
// close count as the same surface in the peel and capture passes.
const float kSameLayer = 1e-6;

const int kColourMonochrome = IVSHADOW_COLOUR_MONOCHROME;  // seeds/000 eq. 5.1
const int kColourSaturate = IVSHADOW_COLOUR_SATURATE;      // eq. 5.3
const int kColourPower = IVSHADOW_COLOUR_POWER;            // eq. 5.2

// Fraction of light (per channel) that passes a surface of colour c.rgb and opacity c.a.
vec3 transmittance(vec4 c, int model) {
  float clear = 1.0 - c.a;
  if (model == kColourSaturate) return clear * clamp(vec3(clear) + c.rgb, 0.0, 1.0);
  if (model == kColourPower) return pow(vec3(clear), 2.0 - c.rgb);
  return vec3(clear);
}

// Coin's texture models (SoMultiTextureImageElement::Model, which are the GL enum values).
const int kTextureNone = 0;
const int kTextureBlend = 0x0BE2;
const int kTextureModulate = 0x2100;
const int kTextureDecal = 0x2101;
const int kTextureReplace = 0x1E01;

vec4 applyTextureModel(vec4 colour, vec4 texel, int model, vec3 blendColour) {
  if (model == kTextureModulate) return colour * texel;
  if (model == kTextureDecal) return vec4(mix(colour.rgb, texel.rgb, texel.a), colour.a);
  if (model == kTextureReplace) return texel;
  if (model == kTextureBlend)
    return vec4(mix(colour.rgb, blendColour, texel.rgb), colour.a * texel.a);
  return colour;
}
