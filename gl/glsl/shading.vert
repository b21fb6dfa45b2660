// Camera pass of SoTransparentShadowGroup: hands Coin's fixed-function inputs to the
// per-pixel shading in shading.frag.
out vec3 vEyePosition;
out vec3 vEyeNormal;

// How GL's fixed-function texgen would make texture unit 0's s, t, r, q for this shape: a GL
// texgen mode each, 0 where the shape's own coordinates hold (gl/TexGenModes.h, kept
// up to date by nodes/TexGenWatchElement). GL's enum values:
const int kObjectLinear = 0x2401;
const int kEyeLinear = 0x2400;
const int kSphereMap = 0x2402;
const int kNormalMap = 0x8511;
const int kReflectionMap = 0x8512;
uniform ivec4 uTexGen;

// The equations of the GL specification (compatibility profile, "Generating Texture
// Coordinates"); the planes are GL's, as Coin's texture coordinate nodes set them.
vec4 textureCoordinate(vec4 eye) {
  vec4 coordinate = gl_MultiTexCoord0;
  if (uTexGen == ivec4(0)) return coordinate;
  vec3 normal = normalize(gl_NormalMatrix * gl_Normal);
  vec3 reflected = reflect(normalize(eye.xyz), normal);
  float m = 2.0 * length(reflected + vec3(0.0, 0.0, 1.0));
  vec2 sphere = reflected.xy / m + 0.5;
  vec4 objectPlanes[4] =
      vec4[4](gl_ObjectPlaneS[0], gl_ObjectPlaneT[0], gl_ObjectPlaneR[0], gl_ObjectPlaneQ[0]);
  vec4 eyePlanes[4] = vec4[4](gl_EyePlaneS[0], gl_EyePlaneT[0], gl_EyePlaneR[0], gl_EyePlaneQ[0]);
  for (int i = 0; i < 4; ++i) {
    int mode = uTexGen[i];
    if (mode == kObjectLinear) coordinate[i] = dot(objectPlanes[i], gl_Vertex);
    if (mode == kEyeLinear) coordinate[i] = dot(eyePlanes[i], eye);
    if (mode == kSphereMap && i < 2) coordinate[i] = sphere[i];
    if (mode == kNormalMap && i < 3) coordinate[i] = normal[i];
    if (mode == kReflectionMap && i < 3) coordinate[i] = reflected[i];
  }
  return coordinate;
}

void main() {
  vec4 eye = gl_ModelViewMatrix * gl_Vertex;
  vEyePosition = eye.xyz / eye.w;
  vEyeNormal = gl_NormalMatrix * gl_Normal;
  gl_FrontColor = gl_Color;
  gl_BackColor = gl_Color;
  gl_TexCoord[0] = gl_TextureMatrix[0] * textureCoordinate(eye);
  gl_FogFragCoord = abs(vEyePosition.z);
  // ftransform() gives the same depth as fixed-function shapes drawn outside the group.
  gl_Position = ftransform();
}
