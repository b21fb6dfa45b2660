// What the lighting reads: the vertex stage's outputs, Coin's coin_* state, and the
// frame's lights and maps (gl/ShadingUniforms.h sets them).

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
// Per light slot: uMapLight, uMapLightEye, uMapParams, uMapColoured, uMapProjection,
// uMapLookup, uMapTexelScale, uMapFaceFirst, uMapFaceLayers, uMapSlices, uMapRay, declared
// from the table in gl/LightSlotFields.h, which says what each holds. Lights with
// method RAYS keep no map: their visibility was traced on the CPU per pixel and per captured
// surface layer (gl/RayShadowPass.h).
IVSHADOW_LIGHT_SLOT_UNIFORMS
uniform sampler2DArray uRayDepth;       // window depth of each captured layer (1: none)
uniform sampler2DArray uRayVisibility;  // layer ray * uRayLayers + captured layer
uniform int uRayLayers;  // the ray textures are indexed by window coordinates

// Each part that follows (lighting.glsl's list) is compiled in only where the frame needs it
// (IVSHADOW_WITH_*: why, in nodes/ShadingProgram.h's ShadingFeatures).
