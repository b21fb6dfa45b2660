#pragma once

#include "ivshadow/Export.h"
#include "ivshadow/ShadowMethod.h"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace ivshadow {

// What building the deep shadow maps of one SoTransparentShadowGroup cost.
struct DeepShadowLightStatistics {
  std::string name;  // the light's DEF name, or "" when it has none
  // Peeled layers that held a surface, per cube face; an opacity map's slices.
  std::array<int, 6> layersUsed{};
  // Draws of the casters per face: a peeled map's passes (early termination), a map built
  // from fragment lists 1 (2 when their storage grew), an opacity map's draws.
  std::array<int, 6> passes{};
  // How a deep shadow map was built: "FRAGMENT_LISTS" (one draw per face) or "PEELING" (one
  // per layer, where the lists could not hold it); "" for other methods.
  std::string mapBuild;
  std::uint64_t listFragments = 0;  // surfaces the lists held, all faces
  // layerOverflow MERGE: the texels whose surfaces were merged (more than maxLayers), all
  // faces, and the largest error (0 .. 1, any channel) that left in their visibility at any
  // distance. A peeled map truncates instead: 0.
  std::uint64_t mergedTexels = 0;
  float mergeError = 0.0f;
  // How the map sees its casters: "CUBE" (a point light, a wide spot light), "PERSPECTIVE"
  // (one face over a spot light's cone) or "ORTHOGRAPHIC" (one face across a directional
  // light); a one-face map counts its layers and passes in face 0. "" without a map.
  std::string projection;
  // An orthographic map's width and height across the light, in the group's units: the
  // casters' extent clipped to what the view shows.
  std::array<float, 2> extent{};
  std::uint64_t bytes = 0;      // GPU memory the map keeps (only layers that are used)
  std::uint64_t peakBytes = 0;  // GPU memory while it was built (all maxLayers)
  bool coloured = false;        // three visibility channels rather than one
  int resolution = 0;
  float nearRadius = 0.0f;
  float farRadius = 0.0f;
  // The method the light cast with, AUTO resolved (Auto only before the light was first
  // built); shadowMethodName gives the name `ivshadow render --stats` writes.
  ShadowMethod method = ShadowMethod::Auto;
};

struct DeepShadowStatistics {
  // How the last render drew the group's children, `renderer AUTO` resolved: "TRACER" (traced
  // whole on the CPU) or "RASTER" (GL's shading with the lights' methods); "" before the group
  // rendered, or while an enclosing group or separator draws its children. Summed over groups
  // (collectDeepShadowStatistics): their one value, or "MIXED".
  std::string renderer;
  std::vector<DeepShadowLightStatistics> lights;
  // GPU time (GL_TIMESTAMP queries) of the last map build, the last shading of the children
  // and the last capture of RAYS surfaces. On llvmpipe the GPU is the CPU rasteriser.
  double gpuBuildMs = 0.0;
  double gpuShadingMs = 0.0;
  double gpuCaptureMs = 0.0;
  // Wall time of the last rebuild, all lights: a deep shadow map's waits for each pass, an
  // opacity map's only sends its draws (gpuBuildMs has their time on the GPU).
  double lastBuildMs = 0.0;
  double totalBuildMs = 0.0;
  int rebuilds = 0;  // times the maps were rebuilt
  int casterTriangles = 0;
  // The RAYS and VOLUMES methods (lights that trace shadow rays or draw shadow volumes for the
  // visible surfaces instead of keeping a map).
  double raysMs = 0.0;            // last trace: capture passes, tracing and upload, wall time
  double rayCaptureMs = 0.0;      // ... of which the capture traversals and read-backs (0 when
                                  //     it traced the surfaces captured before: a moved light)
  double rayTraceMs = 0.0;        // ... the rays on the CPU
  int rayLayers = 0;              // surface layers captured in the last trace
  double bvhBuildMs = 0.0;        // last build of the casters' Embree scene
  std::uint64_t raysTraced = 0;   // last trace
  std::uint64_t volumeFaces = 0;  // last trace: shadow volume triangles of VOLUMES lights
  std::uint64_t bvhBytes = 0;     // what Embree holds for the casters
  int rayFrames = 0;              // frames that traced (others reused an unchanged trace)
  int rayCaptures = 0;            // frames that captured the visible surfaces for their trace
  int bvhBuilds = 0;              // times the casters' Embree scene was built
  int bvhRefits = 0;              // times it was refitted instead (the same triangles moved)
  // One bounce (SoTransparentShadowGroup::bounce), its last placement and map build.
  int bounceLights = 0;           // virtual point lights placed
  int bounceSamples = 0;          // ... of samples traced from the lights (the rest met nothing)
  double bouncePlaceMs = 0.0;     // placing them and the point pool, on the CPU
  double bounceMapMs = 0.0;       // drawing their imperfect shadow maps, on the GPU
  std::uint64_t bounceBytes = 0;  // the maps' atlas, the lights and the point pool in GL
  // A group whose renderer is TRACER (its subgraph traced whole on the CPU).
  double tracerSceneMs = 0.0;   // last read of the subgraph and build of its Embree scenes
  double tracerLightsMs = 0.0;  // last read of its lights alone (a light or the camera moved)
  double tracerMs = 0.0;        // last trace of the picture and its upload, wall time
  int tracerScenes = 0;         // times the subgraph was read
  int tracerFrames = 0;         // frames that traced (others drew the picture kept)
  int tracerWidth = 0;          // the last traced picture's size: the viewport's, or less
  int tracerHeight = 0;         //   while the scene moves (movingResolution)
  std::uint64_t tracerCameraRays = 0;  // last trace (0: it composited the surfaces it kept,
                                       //   as when only a light moved)
  int tracerReduced = 0;               // groups whose last picture is reduced (refined when still)
  int tracerRefines = 0;               // frames that traced a reduced picture again in full
};

}  // namespace ivshadow

class SoNode;

namespace ivshadow {

// Whether the groups and peeling separators time their shading, peel and capture passes on
// the GPU (gpuShadingMs, gpuCaptureMs, PeelStatistics::gpuPeelMs). Reading a GPU timer waits
// for the GPU to finish the pass, so it is off unless a profiler asks: `ivshadow render
// --stats` and the viewer's live figures turn it on. Map builds and the bounce's maps are
// always timed; while it is off, their GPU times (gpuBuildMs, bounceMapMs) are read without
// waiting, once the GPU has them: a build's figure is then the build before's.
IVSHADOW_API void setPassTiming(bool on);
IVSHADOW_API bool passTiming();

// The statistics of every SoTransparentShadowGroup under `root`, summed: lights of all groups
// in traversal order, build times and rebuild counts added up.
IVSHADOW_API DeepShadowStatistics collectDeepShadowStatistics(SoNode* root);

}  // namespace ivshadow

// For hosts that reach the plugin through a C interface (Python's ctypes, as FreeCAD's add-on
// does with a pivy node's address): collectDeepShadowStatistics(root).renderer, as a string
// that lives as long as the program ("" when `root` holds no group or none rendered yet).
extern "C" IVSHADOW_API const char* ivshadow_renderer_in_use(SoNode* root);
