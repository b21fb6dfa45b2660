// What the imperfect shadow maps' build (ism_points.vert) and the one-bounce gather
// (lighting.glsl) must agree on: each virtual point light's frame and how a direction in its
// hemisphere maps to a texel of its tile (a paraboloid, seeds/001 eq. 2.1).

// An orthonormal frame about the unit normal n, without a special case for any direction
// (Duff et al. 2017, "Building an orthonormal basis, revisited").
void bounceFrame(vec3 n, out vec3 t1, out vec3 t2) {
  float s = n.z >= 0.0 ? 1.0 : -1.0;
  float a = -1.0 / (s + n.z);
  float b = n.x * n.y * a;
  t1 = vec3(1.0 + s * n.x * n.x * a, s * b, -s * n.x);
  t2 = vec3(b, s + n.y * n.y * a, -n.y);
}

// The unit direction w in the frame of the light with normal n (z along the normal).
vec3 bounceLocal(vec3 n, vec3 w) {
  vec3 t1, t2;
  bounceFrame(n, t1, t2);
  return vec3(dot(w, t1), dot(w, t2), dot(w, n));
}

// Where the local direction l (l.z >= 0) falls in a tile of size x size texels, in texels:
// the paraboloid maps the hemisphere onto the disc the tile holds.
vec2 bounceTexel(vec3 l, int size) {
  return (l.xy / (1.0 + l.z) * 0.5 + 0.5) * float(size);
}

// The lower-left texel of light `light`'s tile in an atlas of `tiles` x `tiles` tiles.
ivec2 bounceTile(int light, int tiles, int size) {
  return ivec2(light % tiles, light / tiles) * size;
}
