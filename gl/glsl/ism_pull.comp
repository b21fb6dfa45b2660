// Pull (Marroquim et al. 2007, seeds/001): a coarse texel is the mean of its valid 2 x 2
// finer texels, empty when none is. Tiles are powers of two on aligned corners, so a 2 x 2
// block never spans two lights' maps.
layout(local_size_x = IVSHADOW_ISM_GROUP_SIZE, local_size_y = IVSHADOW_ISM_GROUP_SIZE) in;
layout(r32f, binding = IVSHADOW_ISM_READ_UNIT) uniform readonly image2D uFine;
layout(r32f, binding = IVSHADOW_ISM_WRITE_UNIT) uniform writeonly image2D uCoarse;

void main() {
  ivec2 coarse = ivec2(gl_GlobalInvocationID.xy);
  if (any(greaterThanEqual(coarse, imageSize(uCoarse)))) return;
  float sum = 0.0;
  int valid = 0;
  for (int i = 0; i < 4; ++i) {
    float v = imageLoad(uFine, coarse * 2 + ivec2(i & 1, i >> 1)).r;
    if (v < IVSHADOW_ISM_EMPTY) {
      sum += v;
      ++valid;
    }
  }
  imageStore(uCoarse, coarse, vec4(valid > 0 ? sum / float(valid) : IVSHADOW_ISM_EMPTY));
}
