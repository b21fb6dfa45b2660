// A picture traced on the CPU (SoTransparentShadowGroup renderer TRACER) handed to the
// framebuffer: premultiplied colour with the transmittance left in alpha, blended as
// dst = src.rgb + dst * src.a, and the window depth of its nearest opaque surface (or the one
// the framebuffer held, read before the trace) written as the fragment's depth. The picture's
// rows run top to bottom. It covers the viewport whatever its own size. One traced at a lower
// resolution while the scene moves is stretched: each fragment takes the nearest pixel's
// depth, and the bilinear mean of those of the four pixels around it that lie at that depth
// (premultiplied colours, so the mean is compositing's own). Pixels of another surface are
// left out of the mean, so a surface's colour does not bleed over an edge onto what GL drew
// before the group there.
// Compiled twice, with and without STRETCHED: llvmpipe runs both sides of a branch, even on
// a uniform, and the stretched side's fetches made the draw of a picture of the viewport's
// size cost about 8 ms at 800 x 600 on llvmpipe instead of 3 (docs/PERFORMANCE.md).
// The picture is read as images, not through samplers: on llvmpipe the first texel fetch
// cost more than the rest of the draw, and imageLoad took a quarter off it (2.2 to 1.65 ms
// at 400 x 400).
layout(binding = TRACED_COLOUR_UNIT, rgba32f) readonly uniform image2D uColour;
layout(binding = TRACED_DEPTH_UNIT, r32f) readonly uniform image2D uDepth;
uniform ivec2 uOrigin;    // the viewport's corner in window coordinates
uniform ivec2 uSize;      // the viewport's size

// Window depths closer than this are one surface (a slope within one stretched pixel);
// surfaces GL drew apart differ by far more.
const float kSameSurface = 1.0e-3;

layout(location = 0) out vec4 oColour;

void main() {
#ifndef STRETCHED
  // The picture has the viewport's pixels, rows top to bottom.
  ivec2 at = ivec2(gl_FragCoord.xy) - uOrigin;
  ivec2 texel = ivec2(at.x, uSize.y - 1 - at.y);
  gl_FragDepth = imageLoad(uDepth, texel).r;
  oColour = imageLoad(uColour, texel);
#else
  vec2 at = (gl_FragCoord.xy - vec2(uOrigin)) / vec2(uSize);
  at.y = 1.0 - at.y;
  ivec2 pixels = imageSize(uDepth);
  ivec2 nearest = min(ivec2(at * vec2(pixels)), pixels - 1);
  float depth = imageLoad(uDepth, nearest).r;
  gl_FragDepth = depth;
  vec2 texel = at * vec2(pixels) - 0.5;
  ivec2 corner = ivec2(floor(texel));
  vec2 f = texel - vec2(corner);
  vec4 sum = vec4(0.0);
  float weights = 0.0;
  for (int j = 0; j < 2; ++j)
    for (int i = 0; i < 2; ++i) {
      ivec2 p = clamp(corner + ivec2(i, j), ivec2(0), pixels - 1);
      if (abs(imageLoad(uDepth, p).r - depth) > kSameSurface) continue;
      float w = (i == 1 ? f.x : 1.0 - f.x) * (j == 1 ? f.y : 1.0 - f.y);
      sum += w * imageLoad(uColour, p);
      weights += w;
    }
  // The nearest pixel is one of the four and carries the largest weight.
  oColour = weights > 0.0 ? sum / weights : imageLoad(uColour, nearest);
#endif
}
