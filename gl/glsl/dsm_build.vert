// Depth-peeling pass from the light: positions are in the group's coordinates.
layout(location = 0) in vec3 aPosition;
layout(location = 1) in vec4 aColour;
layout(location = 2) in vec2 aTexCoord;

uniform mat4 uViewProjection;

out vec3 vPosition;
out vec4 vColour;
out vec2 vTexCoord;

void main() {
  vPosition = aPosition;
  vColour = aColour;
  vTexCoord = aTexCoord;
  gl_Position = uViewProjection * vec4(aPosition, 1.0);
}
