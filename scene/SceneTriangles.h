#pragma once

#include "ivshadow/Export.h"

#include <Inventor/SbBox3f.h>
#include <Inventor/SbColor.h>

#include <cstddef>
#include <cstdint>
#include <map>
#include <string>
#include <tuple>
#include <vector>

class SoNode;
class SoPath;
class SoCallbackAction;

namespace ivshadow {

// A texture image as Coin holds it (rows bottom-up), widened to RGBA8.
struct TextureImage {
  int width = 0;
  int height = 0;
  std::vector<unsigned char> rgba;
  int model = 0;  // SoMultiTextureImageElement::Model (GL enum values)
  SbColor blendColour{0.0f, 0.0f, 0.0f};
  bool repeatS = true;
  bool repeatT = true;
  bool nearest = false;  // sampled without filtering (low SoComplexity::textureQuality)
  bool grey = true;      // every texel has r == g == b
  bool opaque = true;    // every texel has alpha 255
  // Minified through a mipmap chain, as Coin's SoGLImage does from texture quality 0.5 (its
  // default) on: the two nearest levels blended, within each the nearest texel
  // (GL_NEAREST_MIPMAP_LINEAR) or, from quality 0.8, bilinear (GL_LINEAR_MIPMAP_LINEAR).
  bool mipmapped = false;
  bool bilinearLevels = false;
  // Levels 1, 2, ... of the chain (level 0 is `rgba`): each half the one before, rounded down,
  // to 1 x 1, as GL generates them. Empty unless `mipmapped`.
  struct Level {
    int width = 0;
    int height = 0;
    std::vector<unsigned char> rgba;
  };
  std::vector<Level> levels;
};

// Coin's texture filtering at a texture quality (SoGLImageP::applyFilter with its default
// limits: 0.2 for filtering, 0.5 for mipmaps, 0.8 for bilinear levels), and the mipmap chain
// where it mipmaps.
IVSHADOW_INTERNAL void setTextureFiltering(TextureImage& image, float quality);

struct TriangleVertex {
  float position[3];  // in the coordinates of the node the triangles were taken from
  float colour[4];    // diffuse colour and opacity (1 - transparency)
  float texCoord[2];  // after the texture matrix
};

// Consecutive triangles that share one texture (texture < 0: none).
struct TriangleBatch {
  int texture = -1;
  std::size_t firstVertex = 0;
  std::size_t vertexCount = 0;
};

// The triangles of a subgraph as Coin generates them (SoCallbackAction), so every shape type
// Coin can render is covered, with what a shadow needs of each: where it is, how much light
// it lets through, and its colour.
struct SceneTriangles {
  std::vector<TriangleVertex> vertices;  // three per triangle, grouped into batches
  std::vector<TriangleBatch> batches;
  // Per triangle, in the order of `vertices`: which shape it came from (traversal order), so
  // that two triangles of one surface met on their shared edge count as one surface.
  std::vector<std::uint32_t> shapes;
  std::vector<TextureImage> textures;
  SbBox3f bounds;
  // The triangles that may let light through (a corner not opaque, or a texture with alpha):
  // what an opacity map's slices must span (opaque casters have a depth of their own there).
  SbBox3f transparentBounds;
  bool hasTransparent = false;          // some triangle lets light through
  bool hasColouredTransparent = false;  // ... and is not grey
  // Shapes that should cast but that Coin turns into lines or points (SoLineSet, SoPointSet,
  // SoMarkerSet, ...) or draws as screen-aligned pixels (SoText2, SoImage): they cast nothing.
  // Type and DEF name of each, e.g. "LineSet 'Wire'".
  std::vector<std::string> withoutTriangles;

  std::size_t triangleCount() const { return vertices.size() / 3; }
};

// The triangles under `root` that cast shadows, taken from a default traversal state: those
// whose SoShadowStyle includes CASTS_SHADOW (the default) and that Coin draws filled
// (SoDrawStyle FILLED; LINES and POINTS are listed in `withoutTriangles`, INVISIBLE is left
// out). Fully clear triangles are kept; they cast nothing, which the map builder handles per
// fragment (texture alpha).
IVSHADOW_INTERNAL SceneTriangles extractShadowCasters(SoNode* root);

// The same for the node at the tail of `toGroup` (a path from the scene's root), in the
// traversal state in force there: the materials, complexity, textures, draw style, shape
// hints, units and shadow style set by nodes above it apply, as they do when Coin renders it.
// The triangles are in the tail's own coordinates (transforms above it are undone).
IVSHADOW_INTERNAL SceneTriangles extractShadowCasters(const SoPath* toGroup);

// What Coin's GL rendering fills of a shape that SoCallbackAction turns into triangles
// whatever it is: its triangles (Filled); nothing of them (Unfilled: screen-aligned SoText2
// and SoImage, which give a callback action no primitive, and DrawStyle LINES or POINTS,
// drawn as outlines or points); or nothing at all (Invisible: DrawStyle INVISIBLE).
enum class ShapeFill { Filled, Unfilled, Invisible };
IVSHADOW_INTERNAL ShapeFill shapeFill(SoCallbackAction* action, const SoNode* node);

// A node as messages name it: its type and, when it has one, its DEF name ("LineSet 'Wire'").
IVSHADOW_INTERNAL std::string describeNode(const SoNode* node);

// Whether a colour is grey to within one 8-bit step (such a tint would not show).
IVSHADOW_INTERNAL bool isGrey(float r, float g, float b);

// The current texture of `action` (index into `textures`, added on first use; -1 for none).
// `cache` maps Coin's image data to indices so that each image is copied once.
struct TextureCache {
  std::map<std::tuple<const unsigned char*, int, int, int, int, float>, int> index;
};
IVSHADOW_INTERNAL int currentTexture(SoCallbackAction* action, std::vector<TextureImage>& textures,
                                     TextureCache& cache);

}  // namespace ivshadow
