// RAYS and VOLUMES: the visibility traced or resolved per pixel and captured layer.

#ifdef IVSHADOW_WITH_RAYS
// The traced visibility of the captured surface this fragment is (same depth). A fragment
// deeper than every captured transparent layer takes the layer nearest in depth.
vec3 rayVisibility(int ray) {
  ivec2 pixel = ivec2(gl_FragCoord.xy);
  float z = gl_FragCoord.z;
  int best = -1;
  float bestDistance = 2.0;
  for (int layer = 0; layer < uRayLayers; ++layer) {
    float captured = texelFetch(uRayDepth, ivec3(pixel, layer), 0).r;
    if (captured >= 1.0) continue;
    float distance = abs(captured - z);
    if (distance < bestDistance) {
      best = layer;
      bestDistance = distance;
    }
    // The surface itself (Coin may move a redrawn shape's depth by a few ulps): no need to
    // look at deeper layers.
    if (distance <= 1e-6) break;
  }
  if (best < 0) return vec3(1.0);
  return texelFetch(uRayVisibility, ivec3(pixel, ray * uRayLayers + best), 0).rgb;
}
#endif
