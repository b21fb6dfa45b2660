// Turns the shadow volumes' sums of log transmittance into the visibility the shading
// program reads for a screen-space shadow (RAYS and VOLUMES lights alike), one layer per
// attachment.
uniform sampler2DArray uVolumeSums;
uniform int uVolumeLayers;

layout(location = 0) out vec4 oLayer[IVSHADOW_MAX_SCREEN_LAYERS];

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  for (int layer = 0; layer < IVSHADOW_MAX_SCREEN_LAYERS; ++layer) {
    vec3 sum = layer < uVolumeLayers ? texelFetch(uVolumeSums, ivec3(pixel, layer), 0).rgb
                                     : vec3(0.0);
    oLayer[layer] = vec4(exp(min(sum, vec3(0.0))), 1.0);
  }
}
