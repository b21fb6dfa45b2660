// How a surface colours and filters light, in the one text that both languages compile: the
// GLSL programs have it embedded after deep_shadow_common.glsl (gl/GlProgram.cpp's
// composeShader), and raytrace/SurfaceOptics.cpp includes it with glm's types and functions,
// which GLSL's mirror. So it keeps to what both read alike: constructors instead of
// swizzles, float literals with an f, no overloads. kColourMonochrome, kColourSaturate and
// kColourPower (ShadowColourModel) are defined before it by each language.

// Coin's texture models (SoMultiTextureImageElement::Model, which are the GL enum values).
const int kTextureNone = 0;
const int kTextureBlend = 0x0BE2;
const int kTextureModulate = 0x2100;
const int kTextureDecal = 0x2101;
const int kTextureReplace = 0x1E01;

// Fraction of light (per channel) that passes a surface of colour c.rgb and opacity c.a:
// seeds/000 eq. 5.1 (monochrome), 5.3 (saturate), 5.2 (power).
vec3 transmittance(vec4 c, int model) {
  float clear = 1.0f - c.a;
  if (model == kColourSaturate) return clear * clamp(vec3(clear) + vec3(c), 0.0f, 1.0f);
  if (model == kColourPower) return pow(vec3(clear), 2.0f - vec3(c));
  return vec3(clear);
}

vec4 applyTextureModel(vec4 colour, vec4 texel, int model, vec3 blendColour) {
  if (model == kTextureModulate) return colour * texel;
  if (model == kTextureDecal) return vec4(mix(vec3(colour), vec3(texel), texel.a), colour.a);
  if (model == kTextureReplace) return texel;
  if (model == kTextureBlend)
    return vec4(mix(vec3(colour), blendColour, vec3(texel)), colour.a * texel.a);
  return colour;
}
