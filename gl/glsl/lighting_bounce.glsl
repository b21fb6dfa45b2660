// The one diffuse bounce's gather.

#ifdef IVSHADOW_WITH_BOUNCE
// One diffuse bounce (SoTransparentShadowGroup::bounce): the virtual point lights
// (raytrace/BounceLights.h; position, normal, flux per light in uBounceLights) that see the
// receiver in their imperfect shadow maps (gl/ImperfectShadowMaps.h), summed as
// (1 / pi) flux cos_x cos_i / (r^2 + a^2), each light a disc of radius a (BounceLight), in
// the group's coordinates.
uniform samplerBuffer uBounceLights;
uniform sampler2D uBounceAtlas;
uniform int uBounceCount;
uniform int uBounceTiles;
uniform int uBounceMapSize;
uniform float uBounceLift;
uniform mat3 uEyeToLocalNormal;

vec3 bouncedLight(vec3 x, vec3 n) {
  vec3 sum = vec3(0.0);
  for (int i = 0; i < uBounceCount; ++i) {
    int first = IVSHADOW_BOUNCE_TEXELS_PER_LIGHT * i;
    vec3 y = texelFetch(uBounceLights, first).xyz;
    vec3 ny = texelFetch(uBounceLights, first + 1).xyz;
    vec3 towards = y - x;
    float squared = dot(towards, towards);
    if (!(squared > 0.0)) continue;
    vec3 w = towards * inversesqrt(squared);
    float receiving = dot(n, w);
    float sending = -dot(ny, w);
    if (receiving <= 0.0 || sending <= 0.0) continue;
    // The receiver as the light's map sees it: its direction and distance from the lifted
    // light, hidden when a surface lies nearer that way. It is first moved off its surface
    // towards the light by kIsmNormalOffset texels of the map at its distance (normal-offset
    // shadow mapping), so that the splats of its own surface around it, seen at a slant, lie
    // behind it rather than in front.
    float reach = sqrt(squared);
    vec3 moved = x + n * (IVSHADOW_ISM_NORMAL_OFFSET / float(uBounceMapSize) * reach);
    vec3 d = moved - (y + uBounceLift * ny);
    float distance = length(d);
    vec3 l = bounceLocal(ny, d / distance);
    if (l.z <= 0.0) continue;
    ivec2 texel = bounceTile(i, uBounceTiles, uBounceMapSize) +
                  clamp(ivec2(bounceTexel(l, uBounceMapSize)), ivec2(0), ivec2(uBounceMapSize - 1));
    float stored = texelFetch(uBounceAtlas, texel, 0).r;
    if (distance > stored * (1.0 + IVSHADOW_ISM_BIAS)) continue;
    vec4 flux = texelFetch(uBounceLights, first + 2);  // w: the disc's radius squared
    sum += flux.rgb * (receiving * sending / (squared + flux.w));
  }
  return sum * IVSHADOW_INVERSE_PI;
}
#endif
