// A point's splat: its distance, the nearest kept by MIN blending; texels a splat spills into
// the next tile are not its light's.
in float vDistance;
flat in ivec4 vTile;

layout(location = 0) out vec4 fDistance;

void main() {
  ivec2 texel = ivec2(gl_FragCoord.xy);
  if (any(lessThan(texel, vTile.xy)) || any(greaterThanEqual(texel, vTile.zw))) discard;
  fDistance = vec4(vDistance, 0.0, 0.0, 0.0);
}
