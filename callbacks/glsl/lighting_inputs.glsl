// What the lighting reads: the vertex stage's outputs, Coin's coin_* state, and the
// frame's lights and maps (callbacks/ShadingUniforms.h sets them).

const int kMaxLights = IVSHADOW_MAX_LIGHTS;

in vec3 vEyePosition;
in vec3 vEyeNormal;

// Kept up to date by Coin (SoShaderObject's coin_* parameters).
uniform int coin_light_model;
uniform int coin_two_sided_lighting;
uniform int coin_texunit0_model;
uniform sampler2D textureMap0;

uniform int uLightCount;
uniform mat4 uEyeToLocal;
uniform int uFogType;  // SoEnvironmentElement::FogType

uniform sampler2DArray uMapDepth[kMaxLights];
uniform sampler2DArray uMapVisibility[kMaxLights];
uniform int uMapCount;
uniform vec3 uMapLight[kMaxLights];     // light position in the group's coordinates
uniform vec3 uMapLightEye[kMaxLights];  // ... and in eye coordinates
// resolution, 1 for a directional light (uMapLight*: the direction towards it), bias (texels),
// filter width (texels; 0: the nearest texel)
uniform vec4 uMapParams[kMaxLights];
// How each map sees its casters (IVSHADOW_MAP_*, callbacks/MapFrame.h); for a one-face map the
// group's coordinates to (x w, y w, depth, w); a texel's size at depth d, times the
// resolution: uMapTexelScale.x * d + uMapTexelScale.y.
uniform int uMapProjection[kMaxLights];
uniform mat4 uMapLookup[kMaxLights];
uniform vec2 uMapTexelScale[kMaxLights];
uniform int uMapColoured[kMaxLights];
uniform int uMapFaceFirst[kMaxLights * 6];   // array layer of each face's first layer
uniform int uMapFaceLayers[kMaxLights * 6];  // layers stored for each face
// An opacity map's sliced distances (near, far) and slices per face; z = 0: a deep shadow map.
uniform vec3 uMapSlices[kMaxLights];
// Lights with method RAYS keep no map: their visibility was traced on the CPU per pixel and
// per captured surface layer (callbacks/RayShadowPass.h).
uniform int uMapRay[kMaxLights];  // index among the traced lights, -1 for a map
uniform sampler2DArray uRayDepth;       // window depth of each captured layer (1: none)
uniform sampler2DArray uRayVisibility;  // layer ray * uRayLayers + captured layer
uniform int uRayLayers;  // the ray textures are indexed by window coordinates

// Each part that follows (lighting.glsl's list) is compiled in only where the frame needs it
// (IVSHADOW_WITH_*: why, in nodes/ShadingProgram.h's ShadingFeatures).
