// Camera pass of SoTransparentShadowGroup: hands Coin's fixed-function inputs to the
// per-pixel shading in shading.frag.
out vec3 vEyePosition;
out vec3 vEyeNormal;

void main() {
  vec4 eye = gl_ModelViewMatrix * gl_Vertex;
  vEyePosition = eye.xyz / eye.w;
  vEyeNormal = gl_NormalMatrix * gl_Normal;
  gl_FrontColor = gl_Color;
  gl_BackColor = gl_Color;
  gl_TexCoord[0] = gl_TextureMatrix[0] * gl_MultiTexCoord0;
  gl_FogFragCoord = abs(vEyePosition.z);
  // ftransform() gives the same depth as fixed-function shapes drawn outside the group.
  gl_Position = ftransform();
}
