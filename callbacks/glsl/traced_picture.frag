// A picture traced on the CPU (SoTransparentShadowGroup renderer TRACER) handed to the
// framebuffer: premultiplied colour with the transmittance left in alpha, blended as
// dst = src.rgb + dst * src.a, and the window depth of its nearest opaque surface (or the one
// the framebuffer held, read before the trace) written as the fragment's depth. The picture's
// rows run top to bottom.
uniform sampler2D uColour;
uniform sampler2D uDepth;
uniform ivec2 uOrigin;  // the viewport's corner in window coordinates
uniform int uHeight;    // the picture's rows

layout(location = 0) out vec4 oColour;

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy) - uOrigin;
  pixel.y = uHeight - 1 - pixel.y;
  oColour = texelFetch(uColour, pixel, 0);
  gl_FragDepth = texelFetch(uDepth, pixel, 0).r;
}
