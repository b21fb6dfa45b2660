// Push (seeds/001 fig. 2.16): an empty fine texel takes the four nearest coarser texels
// weighted 9 : 3 : 3 : 1 by nearness, over those that are valid and in its own tile; a valid
// texel keeps what its points gave it. In place: each texel writes only itself and reads the
// coarser level, already final.
layout(local_size_x = IVSHADOW_ISM_GROUP_SIZE, local_size_y = IVSHADOW_ISM_GROUP_SIZE) in;
layout(r32f, binding = IVSHADOW_ISM_READ_UNIT) uniform readonly image2D uCoarse;
layout(r32f, binding = IVSHADOW_ISM_WRITE_UNIT) uniform image2D uFine;
uniform int uCoarseTileSize;  // a tile's side at the coarser level, in its texels

void main() {
  ivec2 fine = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(fine, imageSize(uFine)))) return;
  if (imageLoad(uFine, fine).r < IVSHADOW_ISM_EMPTY) return;
  ivec2 parent = fine / 2;
  ivec2 toward = ivec2((fine.x & 1) == 1 ? 1 : -1, (fine.y & 1) == 1 ? 1 : -1);
  ivec2 low = parent / uCoarseTileSize * uCoarseTileSize;
  ivec2 high = low + ivec2(uCoarseTileSize);
  ivec2 offsets[4] = ivec2[4](ivec2(0), ivec2(toward.x, 0), ivec2(0, toward.y), toward);
  float weights[4] = float[4](9.0, 3.0, 3.0, 1.0);
  float sum = 0.0, weight = 0.0;
  for (int i = 0; i < 4; ++i) {
    ivec2 at = parent + offsets[i];
    if (any(lessThan(at, low)) || any(greaterThanEqual(at, high))) continue;
    float v = imageLoad(uCoarse, at).r;
    if (v >= IVSHADOW_ISM_EMPTY) continue;
    sum += weights[i] * v;
    weight += weights[i];
  }
  if (weight > 0.0) imageStore(uFine, fine, vec4(sum / weight));
}
