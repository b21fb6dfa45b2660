// A picture traced on the CPU (SoTransparentShadowGroup renderer TRACER) handed to the
// framebuffer: premultiplied colour with the transmittance left in alpha, blended as
// dst = src.rgb + dst * src.a, and the window depth of its nearest opaque surface (or the one
// the framebuffer held, read before the trace) written as the fragment's depth. The picture's
// rows run top to bottom. It covers the viewport whatever its own size: one traced at a lower
// resolution while the scene moves is stretched, its colour filtered as the texture is set
// (premultiplied, so interpolating it is compositing's own mean), its depth the nearest
// pixel's (depths of different surfaces have no meaningful mean).
uniform sampler2D uColour;
uniform sampler2D uDepth;
uniform ivec2 uOrigin;  // the viewport's corner in window coordinates
uniform ivec2 uSize;    // the viewport's size

layout(location = 0) out vec4 oColour;

void main() {
  vec2 at = (gl_FragCoord.xy - vec2(uOrigin)) / vec2(uSize);
  at.y = 1.0 - at.y;
  oColour = texture(uColour, at);
  ivec2 pixels = textureSize(uDepth, 0);
  gl_FragDepth = texelFetch(uDepth, min(ivec2(at * vec2(pixels)), pixels - 1), 0).r;
}
