// Shared by the map build and the lookup, so that both agree on the cube layout and on how
// a surface filters light. Included after the #version line.

// Cube face f looks along kFaceAxis[f]; kFaceRight/kFaceUp span its image plane (the
// IVSHADOW_* defines come from gl/ShaderConstants.h).
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

// The colour models' ids (ShadowColourModel), which scene/surface_optics.glsl, embedded after
// this file, branches on.
const int kColourMonochrome = IVSHADOW_COLOUR_MONOCHROME;
const int kColourSaturate = IVSHADOW_COLOUR_SATURATE;
const int kColourPower = IVSHADOW_COLOUR_POWER;
