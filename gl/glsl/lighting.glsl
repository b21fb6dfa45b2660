// Coin's lighting (the fixed-function equations Coin programs through glLight/glMaterial)
// evaluated per pixel, with each deep shadow light's contribution multiplied by the
// visibility looked up in its deep shadow map (a cube, or one face): shade(), shared by the camera pass
// (shading.frag) and the peel passes (peel.frag), which put their main() after it.
//
// One file per concern, put together when the shaders are embedded (cmake/EmbedGlslScript.cmake
// replaces each #include line with the file it names, from this folder).
#include "lighting_inputs.glsl"
#include "lighting_rays.glsl"
#include "lighting_opacity_maps.glsl"
#include "lighting_deep_maps.glsl"
#include "lighting_lights.glsl"
#include "lighting_bounce.glsl"
#include "lighting_shade.glsl"
