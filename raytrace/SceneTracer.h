#pragma once

#include "ivshadow/Export.h"
#include "raytrace/CasterScene.h"
#include "scene/ShadowTypes.h"

#include <Inventor/SbBox3f.h>
#include <Inventor/SbMatrix.h>

#include <atomic>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

class SoCallbackAction;
class SoNode;
class SoPath;

namespace ivshadow {

// The surfaces each pixel's ray met in a trace: every surface up to the nearest opaque one,
// in exact depth order, and the window depth found. A later trace of the same view (the same
// camera, size, depth limit and triangles; only the lights moved) composites them again
// without tracing the camera rays (TraceOptions::surfaces).
struct SurfacesMet {
  struct Hit {
    float t;  // along the pixel's ray from the near plane (0) to the far plane (1)
    std::uint32_t primitive;
    float u;
    float v;
  };
  struct Row {
    std::vector<Hit> hits;
    std::vector<std::uint32_t> ends;  // where each pixel's hits end in `hits`
    std::vector<float> depth;         // each pixel's window depth
    // The shadow rays its surfaces asked for when last shaded (of which casters), and their
    // answers: a trace that asks the same of the same casters (a light's intensity or colour
    // changed, not where it is) takes the answers again instead of tracing the rays.
    std::vector<CasterScene::Query> queries;
    std::vector<const CasterScene*> queryCasters;
    std::vector<glm::vec3> answers;
  };
  std::vector<Row> rows;
};

// How a trace runs: its size, its threads, how it stops early and how much bounce it
// samples.
struct TraceOptions {
  int width = 800;
  int height = 600;
  int threads = 0;  // 0: every core
  // Read by the workers between rows: set it (from a signal handler) to stop early.
  const std::atomic<bool>* cancel = nullptr;
  // Rows finished so far, updated as the workers go; may be read from another thread.
  std::atomic<int>* rowsDone = nullptr;
  // Cosine-weighted rays per shaded point for the bounce of a group whose bounce field is
  // TRUE (rounded up to a square, stratified; 0: no bounce).
  int bounceSamples = 256;
  // When set, the surfaces the camera rays meet are kept there; with reuseSurfaces, those
  // kept (by a trace of the same view) are composited instead of tracing the camera rays.
  SurfacesMet* surfaces = nullptr;
  bool reuseSurfaces = false;
  // The viewport GL stretches the picture over (a reduced picture while the scene moves): the
  // polygon offset's depth slope is per viewport pixel, as GL's. 0: the picture's own size.
  int viewportWidth = 0;
  int viewportHeight = 0;
  // The depth buffer GL draws over the picture with: the depth of faces under SoPolygonOffset
  // is offset as GL offsets them there, so that lines drawn on them stay in front. None: no
  // offset.
  DepthBuffer depthBuffer;
};

// What a trace gives for each pixel, rows top to bottom: the surfaces met, composited front
// to back (rgb premultiplied: the light they send; a: the transmittance left for what lies
// behind them), and the window depth (0 .. 1, GL's default depth range) of the nearest opaque
// surface, or the limit it was given where there is none.
struct TracedPixels {
  int width = 0;
  int height = 0;
  std::vector<float> rgba;
  std::vector<float> depth;
  std::size_t cameraRays = 0;  // 0 when the surfaces kept were composited again
  std::size_t shadowRays = 0;
  std::size_t bounceRays = 0;
};

// The exact picture of a scene's triangles, computed on the CPU with Embree: the camera,
// lights, materials, textures and every shape Coin can turn into triangles are read once
// through a SoCallbackAction. Each pixel's ray meets every surface and composites them in
// exact depth order; each surface is shaded with the GL path's per-pixel Coin lighting, and
// every casting light of an active SoTransparentShadowGroup is attenuated by the
// transmittance of every caster of that group between the point and the light (same colour
// model, same SoShadowStyle rules). The reference renderer traces a whole scene with it; a
// group whose renderer is TRACER traces its own subgraph (fromPath) and hands the picture to
// GL.
class IVSHADOW_INTERNAL SceneTracer {
 public:
  // The scene below `root`, made ready for viewing (its camera is the one traced by
  // trace(options)). Throws std::runtime_error when Embree fails.
  static std::unique_ptr<SceneTracer> fromScene(SoNode* root, int width, int height);
  // What `path` (from a scene's root to a node) leads to, in the state in force there: the
  // lights met on the way light it, as in the scene. Throws as fromScene.
  static std::unique_ptr<SceneTracer> fromPath(const SoPath* path, int width, int height);
  ~SceneTracer();
  SceneTracer(const SceneTracer&) = delete;
  SceneTracer& operator=(const SceneTracer&) = delete;

  // Reads the lights on the way to and below `path` again (the one fromPath read), and
  // where they are, without the shapes: what a moved light or camera changes. False when
  // the groups below are not the ones read (read the path again).
  bool updateLights(const SoPath* path);
  // Whether the picture depends on the camera beyond its rays: a fog whose distance is the
  // view volume's (visibility 0), read with the triangles.
  bool viewDependent() const;

  // Whether a camera was met before a triangle, and its matrices.
  bool haveCamera() const;
  const SbMatrix& viewing() const;
  const SbMatrix& projection() const;
  std::size_t triangles() const;
  // The box around the triangles, in the world.
  SbBox3f bounds() const;
  // The shapes drawn with lines, points or screen-aligned pixels, which are not traced: as
  // described for a message, and as the child indices of their paths from the root traced (for
  // GL to draw them; index 0, the root's, unused).
  const std::vector<std::string>& untracedShapes() const;
  const std::vector<std::vector<int>>& untracedPaths() const;

  // Traces the picture seen through `viewing` and `projection` (world to eye, eye to clip).
  // `depthLimit` (width x height window depths, rows bottom to top as GL reads them; may be
  // null) ends each pixel's ray there: what GL drew before hides what lies behind it. Returns
  // false when cancelled.
  bool trace(const SbMatrix& viewing, const SbMatrix& projection, const float* depthLimit,
             const TraceOptions& options, TracedPixels& out) const;
  // The same with the camera met in the scene.
  bool trace(const TraceOptions& options, TracedPixels& out) const;

 private:
  struct Data;
  static std::unique_ptr<Data> extract(int width, int height,
                                       const std::function<void(SoCallbackAction&)>& apply);
  explicit SceneTracer(std::unique_ptr<Data> data);
  std::unique_ptr<Data> data_;
  // The workers' working memory, kept from one trace to the next (SceneTracer.cpp).
  struct Workers;
  std::unique_ptr<Workers> workers_;
};

}  // namespace ivshadow
