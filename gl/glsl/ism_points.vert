// The imperfect shadow maps (gl/ImperfectShadowMaps.h): instance i draws its share of
// the point pool into tile i of the atlas, each point at its paraboloid texel in light i's
// hemisphere and holding its distance from the light. Points behind the light are clipped.
uniform samplerBuffer uIsmPoints;
uniform samplerBuffer uBounceLights;
uniform int uIsmTiles;
uniform int uIsmMapSize;
uniform int uIsmStride;  // pool size over points per light
uniform float uBounceLift;

out float vDistance;
flat out ivec4 vTile;  // the tile's texels: x, y from (inclusive) to z, w (exclusive)

void main() {
  int light = gl_InstanceID;
  vec3 point = texelFetch(uIsmPoints, gl_VertexID * uIsmStride + light % uIsmStride).xyz;
  vec3 position = texelFetch(uBounceLights, IVSHADOW_BOUNCE_TEXELS_PER_LIGHT * light).xyz;
  vec3 normal = texelFetch(uBounceLights, IVSHADOW_BOUNCE_TEXELS_PER_LIGHT * light + 1).xyz;
  vec3 d = point - (position + uBounceLift * normal);
  float distance = length(d);
  vec3 l = distance > 0.0 ? bounceLocal(normal, d / distance) : vec3(0.0, 0.0, -1.0);
  gl_ClipDistance[0] = l.z;
  ivec2 tile = bounceTile(light, uIsmTiles, uIsmMapSize);
  vec2 atlas = vec2(tile) + bounceTexel(l, uIsmMapSize);
  gl_Position = vec4(atlas / float(uIsmTiles * uIsmMapSize) * 2.0 - 1.0, 0.0, 1.0);
  gl_PointSize = IVSHADOW_ISM_POINT_SIZE;
  vDistance = distance;
  vTile = ivec4(tile, tile + ivec2(uIsmMapSize));
}
