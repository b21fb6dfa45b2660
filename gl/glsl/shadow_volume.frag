// Transparent shadow volumes, z-fail (seeds/003, seeds/004): for each captured layer of
// visible surfaces, every volume face beyond the surface adds its weight (log transmittance)
// where it leaves the volume, seen from the eye, and subtracts it where it enters, so the
// additive blend leaves the sum over the volumes that hold the surface: its log visibility.
// Counting beyond the surface, never in front, lets the camera stand inside a volume; faces
// past the far plane are kept by depth clamping and compared here, not by the depth test.
flat in vec3 vWeight;
in float vDistance;

// Each captured layer's position in the group's coordinates; w its window depth, 1 where
// nothing is traced.
uniform sampler2DArray uVolumePosition;
uniform int uVolumeLayers;
uniform mat4 uLocalToEye;
// -1 where the group's coordinates are mirrored on the way to the eye (the faces' winding
// then reads the other way round).
uniform float uWinding;

layout(location = 0) out vec4 oLayer[IVSHADOW_MAX_SCREEN_LAYERS];

void main() {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  float leaving = gl_FrontFacing ? -uWinding : uWinding;
  // Coincident: an entering face is beyond the surface, a leaving one in front of it.
  float tolerance = leaving * IVSHADOW_VOLUME_DEPTH_TOLERANCE;
  for (int layer = 0; layer < IVSHADOW_MAX_SCREEN_LAYERS; ++layer) {
    vec4 add = vec4(0.0);
    vec4 captured =
        layer < uVolumeLayers ? texelFetch(uVolumePosition, ivec3(pixel, layer), 0) : vec4(1.0);
    if (captured.w < 1.0) {
      float surface = -(uLocalToEye * vec4(captured.xyz, 1.0)).z;
      if (vDistance >= surface + tolerance * abs(surface))
        add = vec4(leaving * vWeight, 0.0);
    }
    oLayer[layer] = add;
  }
}
