// The faces of a VOLUMES light's shadow volumes (raytrace/ShadowVolumes): corners in the
// group's coordinates, each face with one weight.
layout(location = 0) in vec4 aPosition;
layout(location = 1) in vec4 aWeight;

uniform mat4 uLocalToClip;
uniform mat4 uLocalToEye;

flat out vec3 vWeight;
out float vDistance;  // along the view axis, from the eye

void main() {
  gl_Position = uLocalToClip * aPosition;
  vec4 eye = uLocalToEye * aPosition;
  vDistance = -eye.z / eye.w;
  vWeight = aWeight.rgb;
}
