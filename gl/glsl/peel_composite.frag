// Compositing of SoPeelingSeparator's layers (seeds/000 eq. 2.5-2.8).
//  uStep 0: hands this pass's back layer to "over" blending into the back accumulation.
//  uStep 1: front layers (rgb, 1 - transmittance) over the back accumulation
//           (rgb, transmittance); blended onto the opaque picture as
//           dst = src.rgb + dst * src.a (eq. 2.8).
uniform int uStep;
uniform sampler2D uBackLayer;
uniform sampler2D uFront;
uniform sampler2D uBackAccumulation;

layout(location = 0) out vec4 oColour;

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  if (uStep == 0) {
    oColour = texelFetch(uBackLayer, pixel, 0);
    return;
  }
  vec4 front = texelFetch(uFront, pixel, 0);
  vec4 back = texelFetch(uBackAccumulation, pixel, 0);
  float transmittance = 1.0 - front.a;
  oColour = vec4(front.rgb + transmittance * back.rgb, transmittance * back.a);
}
