// Capture passes for RAYS lights: attachment 0 gets the surface's position in the group's
// coordinates and its window depth, attachment 1 its geometric normal and 2.0 in alpha (a
// shape Coin draws without this program writes a colour, alpha <= 1, and is not traced).
// Variant IVSHADOW_CAPTURE_OPAQUE catches the nearest opaque surface; without it the program
// catches the nearest transparent surface behind the previous capture and in front of the
// opaque one.
in vec3 vEyePosition;

// Kept up to date by Coin (SoShaderObject's coin_* parameters).
uniform int coin_texunit0_model;
uniform sampler2D textureMap0;

uniform mat4 uEyeToLocal;
uniform sampler2D uRayOpaque;    // the opaque capture (alpha: window depth)
uniform sampler2D uRayPrevious;  // the previous transparent capture
uniform int uRayFirstTransparent;

void main() {
  vec4 texel = coin_texunit0_model != kTextureNone ? texture(textureMap0, gl_TexCoord[0].st)
                                                   : vec4(1.0);
  float alpha =
      applyTextureModel(gl_Color, texel, coin_texunit0_model, gl_TextureEnvColor[0].rgb).a;
  // Derivatives first: after a discard they are undefined.
  vec3 local = (uEyeToLocal * vec4(vEyePosition, 1.0)).xyz;
  vec3 normal = cross(dFdx(local), dFdy(local));
  if (alpha <= 0.0) discard;
  float z = gl_FragCoord.z;
#ifdef IVSHADOW_CAPTURE_OPAQUE
  if (!isOpaque(alpha)) discard;
#else
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  if (isOpaque(alpha)) discard;
  if (z >= texelFetch(uRayOpaque, pixel, 0).a - kSameLayer) discard;
  if (uRayFirstTransparent == 0 && z <= texelFetch(uRayPrevious, pixel, 0).a + kSameLayer)
    discard;
#endif
  gl_FragData[0] = vec4(local, z);
  gl_FragData[1] = vec4(normal, 2.0);
}
