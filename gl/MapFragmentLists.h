#pragma once

#include "gl/GlHandles.h"
#include "gl/GlProgram.h"

#include <array>
#include <cstdint>
#include <map>
#include <memory>
#include <string>

namespace ivshadow {

class CasterBuffers;
struct MapRequest;

// What the lists of one face hold, as the layer passes would count it: bit k, layer k of some
// texel holds a surface (heldLayers), one that lets light through (passingLayers); and
// whether some texel has a closing layer.
struct MapListFace {
  std::array<std::uint32_t, 2> heldLayers{};
  std::array<std::uint32_t, 2> passingLayers{};
  bool closingLayer = false;
  // With MapRequest::mergeOverflow: the texels whose surfaces are merged.
  std::uint32_t mergedTexels = 0;
};

// Where a map's layers go: face f's `layers[f]` layers from array layer firstLayer[f] on, of
// the two arrays (GL names: r32f distances; visibilities of the request's format).
struct MapListLayout {
  std::array<int, 6> firstLayer{};
  std::array<int, 6> layers{};
  unsigned int depthArray = 0;
  unsigned int visibilityArray = 0;
};

// A deep shadow map's faces from per-texel fragment lists in one GL context (after Yang et
// al. 2010, as FragmentListPass for the camera): one draw of the casters per face links every
// surface into its texel's list, and a compute pass sorts each list into the layers the layer
// passes would have stored (dsm_list_resolve.comp), so the map is the same without one pass
// per layer. A build is
//   gather(); <size the map from what it found>; store();
// or, where the last build's layout is given and still holds, gather() alone.
// The list buffer (kMapFragmentBytes a surface, all faces at once) and the heads are kept
// between builds and grow to what a map needs, up to what GL gives.
class MapFragmentLists {
 public:
  // Null, with the reason, when the list program does not link or its flags cannot be had.
  static std::unique_ptr<MapFragmentLists> create(std::string& whyNot);
  ~MapFragmentLists();

  // Links every face's surfaces into the lists and says what each face's lists hold. The
  // draws use `textureUnit` for the casters' textures. GL state is left changed: the caller
  // saves and restores it around the build (GlStateScope, with kImageBindings). `byteLimit`
  // (0: GL's limits only) bounds the list storage. With `guess`, the layout of the last build,
  // the same pass also stores the layers there: where what it says matches the guess the map
  // is done without store(). Empty when every surface was stored; else why the lists could
  // not hold the map (the caller builds it layer by layer instead).
  std::string gather(const MapRequest& request, const CasterBuffers& casters, int textureUnit,
                     std::uint64_t byteLimit, const MapListLayout* guess,
                     std::array<MapListFace, 6>& faces);
  // After a gather(): writes each face's layers in `layout`, every texel of them.
  void store(const MapRequest& request, const MapListLayout& layout);
  // With MapRequest::mergeOverflow, after the layers were stored: the largest error in
  // visibility (0 .. 1, any channel) the merge left in a texel, over all faces.
  float mergeError() const;
  // Draws of the casters per face in the last gather: 1, or 2 when the storage grew.
  int passes() const { return passes_; }
  // Surfaces the last gather stored, all faces.
  std::uint64_t fragments() const { return used_; }
  // GPU memory the lists keep (buffer and heads).
  std::uint64_t bytes() const;

 private:
  MapFragmentLists() = default;
  // The resolve program for `request`: storing or only counting. Null with why when it does
  // not link.
  const GlProgram* resolveProgram(const MapRequest& request, bool storing, std::string& whyNot);
  // A compute program of the lists (after dsm_list_common.glsl) with `defines`, linked once.
  const GlProgram* computeProgram(const std::string& defines, const char* source, const char* what,
                                  std::string& whyNot);
  std::string allocateHeads(int size, int faces);
  std::string allocateList(std::uint64_t fragments, std::uint64_t byteLimit);
  // The queue of texels to merge, one word for every texel of the faces.
  std::string allocateMergeQueue(std::uint64_t texels);
  // The merge program (dsm_list_merge.comp) for `request`; null with why when it does not link.
  const GlProgram* mergeProgram(const MapRequest& request, std::string& whyNot);
  // Merges the texels the storing resolve just queued, into `layout`.
  void merge(const MapRequest& request, const MapListLayout& layout);
  void fill(const MapRequest& request, const CasterBuffers& casters, int textureUnit);
  void resolve(const MapRequest& request, const GlProgram& program, int face);
  // Runs `program` over the lists of the faces marked in `faces`, storing into `layout` where
  // it has arrays.
  void resolveInto(const MapRequest& request, const GlProgram& program, const MapListLayout& layout,
                   const std::array<bool, 6>& faces);

  GlProgram fill_;
  // Resolve and merge programs by their defines (the sort's size, storing or not, merging or
  // not, the visibility format), linked when a map first needs one; with why one did not.
  std::map<std::string, GlProgram> compute_;
  std::map<std::string, std::string> computeError_;
  GlBuffer list_;
  GlBuffer flags_;
  GlBuffer mergeQueue_;
  std::uint64_t mergeQueueTexels_ = 0;
  GlTexture heads_;            // one layer per face
  GlFramebuffer framebuffer_;  // no attachments: the fill writes only the buffer
  int size_ = 0;
  int faces_ = 0;
  std::uint64_t capacity_ = 0;  // fragments the list buffer holds
  std::uint64_t maxBytes_ = 0;  // GL_MAX_SHADER_STORAGE_BLOCK_SIZE
  std::uint64_t used_ = 0;
  int passes_ = 0;
};

}  // namespace ivshadow
