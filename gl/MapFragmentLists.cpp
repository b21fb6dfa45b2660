#include "gl/MapFragmentLists.h"

#include "GlslSources.h"
#include "gl/CasterBuffers.h"
#include "gl/DeepShadowMap.h"
#include "gl/GlAllocationCheck.h"
#include "gl/ShaderConstants.h"

#include <epoxy/gl.h>
#include <glm/gtc/type_ptr.hpp>

#include <algorithm>
#include <cstring>

namespace ivshadow {
namespace {

// The list buffer's header (dsm_list_common.glsl): used, capacity and two unused words.
constexpr std::uint64_t kHeaderBytes = 16;
constexpr GLuint kNoFragment = 0xffffffffu;
// The flags buffer: kMapFaceFlags words per face that the counting resolve sets, then per face
// the list's count of fragments after that face's draw, copied there by the GL between draws
// so that a face without surfaces is found without waiting after each draw.
constexpr GLintptr kCountsOffset = 6 * kMapFaceFlags * sizeof(GLuint);
constexpr GLsizeiptr kFlagsBytes = kCountsOffset + 6 * sizeof(GLuint);
// The merge queue's header (dsm_list_common.glsl): the merge's indirect dispatch (groups, 1,
// 1) and the texels queued.
constexpr std::uint64_t kMergeHeaderBytes = 16;

// The sort's size: maxLayers rounded up to a power of two, so that a light whose maxLayers
// changes links a new program only when it crosses one (7 sizes for 1 .. kMaxMapLayers).
int sortSize(int layers) {
  int size = 1;
  while (size < layers) size *= 2;
  return size;
}

GLenum visibilityFormat(const MapRequest& request) {
  return request.coloured ? (request.halfPrecision ? GL_RGBA16F : GL_RGBA32F)
                          : (request.halfPrecision ? GL_R16F : GL_R32F);
}

const char* visibilityQualifier(const MapRequest& request) {
  return request.coloured ? (request.halfPrecision ? "rgba16f" : "rgba32f")
                          : (request.halfPrecision ? "r16f" : "r32f");
}

GLuint groups(int size) {
  return GLuint((size + kMapResolveGroupSize - 1) / kMapResolveGroupSize);
}

std::string megabytes(std::uint64_t bytes) {
  return std::to_string(bytes >> 20) + " MiB";
}

}  // namespace

std::unique_ptr<MapFragmentLists> MapFragmentLists::create(std::string& whyNot) {
  // Made by a DeepShadowPass, which has checked for OpenGL 4.5 (image atomics, shader
  // storage, compute and framebuffers without attachments).
  std::unique_ptr<MapFragmentLists> lists(new MapFragmentLists);
  std::string why;
  lists->fill_ = GlProgram::link(
      composeShader(glsl::kDsmBuildVert),
      composeShader(std::string(glsl::kDsmListCommonGlsl) + glsl::kDsmListFrag), why);
  if (!lists->fill_) {
    whyNot = "the fragment lists' program failed: " + why;
    return nullptr;
  }
  GLint64 maxBytes = 0;
  glGetInteger64v(GL_MAX_SHADER_STORAGE_BLOCK_SIZE, &maxBytes);
  lists->maxBytes_ = std::uint64_t(std::max<GLint64>(maxBytes, 0));
  clearGlErrors();
  lists->flags_ = createBuffer();
  glNamedBufferData(lists->flags_.get(), kFlagsBytes, nullptr, GL_DYNAMIC_READ);
  const std::string failure = glAllocationError(GlAllocation::Buffer);
  if (!failure.empty()) {
    whyNot = "GL could not allocate the fragment lists' flags (" + failure + ")";
    return nullptr;
  }
  lists->framebuffer_ = createFramebuffer();
  labelGlObject(GL_BUFFER, lists->flags_.get(), "map fragment lists flags");
  labelGlObject(GL_FRAMEBUFFER, lists->framebuffer_.get(), "map fragment lists target");
  return lists;
}

MapFragmentLists::~MapFragmentLists() = default;

std::uint64_t MapFragmentLists::bytes() const {
  return (capacity_ > 0 ? kHeaderBytes + capacity_ * std::uint64_t(kMapFragmentBytes) : 0u) +
         std::uint64_t(size_) * std::uint64_t(size_) * std::uint64_t(faces_) * 4u +
         (mergeQueueTexels_ > 0 ? kMergeHeaderBytes + mergeQueueTexels_ * 4u : 0u);
}

const GlProgram* MapFragmentLists::resolveProgram(const MapRequest& request, bool storing,
                                                  std::string& whyNot) {
  std::string defines =
      "#define IVSHADOW_MAP_LIST_LAYERS " + std::to_string(sortSize(request.layers)) + "\n";
  if (request.mergeOverflow) defines += "#define IVSHADOW_MAP_LIST_MERGE\n";
  if (storing)
    defines += std::string(
                   "#define IVSHADOW_MAP_LIST_STORE\n#define "
                   "IVSHADOW_MAP_VISIBILITY_FORMAT ") +
               visibilityQualifier(request) + "\n";
  return computeProgram(defines, glsl::kDsmListResolveComp, "resolve", whyNot);
}

const GlProgram* MapFragmentLists::mergeProgram(const MapRequest& request, std::string& whyNot) {
  const std::string defines =
      "#define IVSHADOW_MAP_LIST_LAYERS " + std::to_string(sortSize(request.layers)) +
      "\n#define IVSHADOW_MAP_VISIBILITY_FORMAT " + visibilityQualifier(request) + "\n";
  return computeProgram(defines, glsl::kDsmListMergeComp, "merge", whyNot);
}

const GlProgram* MapFragmentLists::computeProgram(const std::string& defines, const char* source,
                                                  const char* what, std::string& whyNot) {
  const std::string key = std::string(what) + "\n" + defines;
  GlProgram& program = compute_[key];
  std::string& error = computeError_[key];
  if (!program && error.empty()) {
    std::string why;
    program = GlProgram::linkCompute(
        composeShader(std::string(glsl::kDsmListCommonGlsl) + source, defines), why);
    if (!program) error = std::string("the fragment lists' ") + what + " program failed: " + why;
    labelGlObject(GL_PROGRAM, program.name(), std::string("map fragment lists ") + what);
  }
  whyNot = error;
  return program ? &program : nullptr;
}

std::string MapFragmentLists::allocateMergeQueue(std::uint64_t texels) {
  if (texels <= mergeQueueTexels_) return {};
  mergeQueue_.reset();
  mergeQueueTexels_ = 0;
  clearGlErrors();
  GlBuffer queue = createBuffer();
  glNamedBufferData(queue.get(), GLsizeiptr(kMergeHeaderBytes + texels * 4u), nullptr,
                    GL_DYNAMIC_COPY);
  const std::string failure = glAllocationError(GlAllocation::FragmentList);
  if (!failure.empty())
    return "GL could not allocate the queue of texels to merge (" + failure + ")";
  mergeQueue_ = std::move(queue);
  mergeQueueTexels_ = texels;
  return {};
}

std::string MapFragmentLists::allocateHeads(int size, int faces) {
  if (size == size_ && faces == faces_) return {};
  size_ = faces_ = 0;
  clearGlErrors();
  heads_ = createTargetArray(GL_R32UI, size, faces);
  const std::string failure = glAllocationError(GlAllocation::Texture);
  if (!failure.empty()) return "GL could not allocate the fragment lists' heads (" + failure + ")";
  // Without attachments the framebuffer's size is its default one.
  glNamedFramebufferParameteri(framebuffer_.get(), GL_FRAMEBUFFER_DEFAULT_WIDTH, size);
  glNamedFramebufferParameteri(framebuffer_.get(), GL_FRAMEBUFFER_DEFAULT_HEIGHT, size);
  const std::string incomplete = framebufferIncompleteness(framebuffer_.get());
  if (!incomplete.empty())
    return "the fragment lists' framebuffer is incomplete (" + incomplete + ")";
  size_ = size;
  faces_ = faces;
  return {};
}

std::string MapFragmentLists::allocateList(std::uint64_t fragments, std::uint64_t byteLimit) {
  const std::uint64_t bytes = kHeaderBytes + fragments * std::uint64_t(kMapFragmentBytes);
  const bool budget = byteLimit > 0 && byteLimit < maxBytes_;
  const std::uint64_t limit = budget ? byteLimit : maxBytes_;
  // The header's counters are 32-bit.
  if (bytes > limit || fragments >= kNoFragment)
    return "the map needs " + megabytes(bytes) + " of fragment lists, more than the " +
           megabytes(limit) + (budget ? " the memory budget leaves" : " GL gives");
  clearGlErrors();
  GlBuffer list = createBuffer();
  glNamedBufferData(list.get(), GLsizeiptr(bytes), nullptr, GL_DYNAMIC_COPY);
  const std::string failure = glAllocationError(GlAllocation::FragmentList);
  if (!failure.empty()) return "GL could not allocate the fragment lists (" + failure + ")";
  list_ = std::move(list);
  capacity_ = fragments;
  const GLuint header[4] = {0u, GLuint(capacity_), 0u, 0u};
  glNamedBufferSubData(list_.get(), 0, sizeof(header), header);
  return {};
}

void MapFragmentLists::fill(const MapRequest& request, const CasterBuffers& casters,
                            int textureUnit) {
  const GLuint zero = 0u;
  glClearTexImage(heads_.get(), 0, GL_RED_INTEGER, GL_UNSIGNED_INT, &kNoFragment);
  glClearNamedBufferSubData(list_.get(), GL_R32UI, 0, sizeof(GLuint), GL_RED_INTEGER,
                            GL_UNSIGNED_INT, &zero);
  glClearNamedBufferSubData(flags_.get(), GL_R32UI, 0, kCountsOffset, GL_RED_INTEGER,
                            GL_UNSIGNED_INT, &zero);
  glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.get());
  glViewport(0, 0, request.resolution, request.resolution);
  // The layer passes' clipping (MapFrame: reversed depth in [0, 1]), without their depth test.
  glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
  glDisable(GL_DEPTH_TEST);
  glUseProgram(fill_.name());
  fill_.setInt("uColourModel", static_cast<int>(request.colourModel));
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, GLuint(kFragmentListBinding), list_.get());
  for (int face = 0; face < request.frame.faceCount; ++face) {
    const MapFace& view = request.frame.faces[std::size_t(face)];
    fill_.setMat4("uViewProjection", glm::value_ptr(view.viewProjection));
    fill_.setVec3("uDepthOrigin", glm::value_ptr(view.depthOrigin));
    fill_.setVec3("uDepthAxis", glm::value_ptr(view.depthAxis));
    glBindImageTexture(GLuint(kFragmentHeadsUnit), heads_.get(), 0, GL_FALSE, face, GL_READ_WRITE,
                       GL_R32UI);
    casters.draw(fill_, textureUnit);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    glCopyNamedBufferSubData(list_.get(), flags_.get(), 0,
                             kCountsOffset + GLintptr(face) * GLintptr(sizeof(GLuint)),
                             sizeof(GLuint));
  }
  // The resolve reads what the draws wrote; the next fill clears the heads they exchanged.
  glMemoryBarrier(GL_SHADER_STORAGE_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT |
                  GL_TEXTURE_UPDATE_BARRIER_BIT);
}

void MapFragmentLists::resolve(const MapRequest& request, const GlProgram& program, int face) {
  program.setInt("uFace", face);
  glDispatchCompute(groups(request.resolution), groups(request.resolution), 1);
}

std::string MapFragmentLists::gather(const MapRequest& request, const CasterBuffers& casters,
                                     int textureUnit, std::uint64_t byteLimit,
                                     const MapListLayout* guess,
                                     std::array<MapListFace, 6>& faces) {
  faces = {};
  used_ = 0;
  passes_ = 0;
  std::string failure;
  const GlProgram* counting = resolveProgram(request, false, failure);
  if (counting == nullptr) return failure;
  const GlProgram* storing = resolveProgram(request, true, failure);
  if (storing == nullptr) return failure;
  if (request.mergeOverflow && mergeProgram(request, failure) == nullptr) return failure;
  failure = allocateHeads(request.resolution, request.frame.faceCount);
  if (!failure.empty()) return failure;
  const std::uint64_t texels = std::uint64_t(request.resolution) *
                               std::uint64_t(request.resolution) *
                               std::uint64_t(request.frame.faceCount);
  // One surface for every two texels of the faces to begin with (most of a cube's faces see
  // few casters; a quarter of that where GL gives no more); a map that needs more grows the
  // buffer and is drawn again, and the buffer stays for the next build.
  // A buffer kept from a build with more room than this one may take is made again.
  if (capacity_ > 0 && byteLimit > 0 &&
      kHeaderBytes + capacity_ * std::uint64_t(kMapFragmentBytes) > byteLimit) {
    list_.reset();
    capacity_ = 0;
  }
  if (capacity_ == 0) {
    failure = allocateList(texels / 2u + 1u, byteLimit);
    if (!failure.empty()) failure = allocateList(texels / 8u + 1u, byteLimit);
    if (!failure.empty()) return failure;
  }
  if (request.mergeOverflow) {
    // The queue names a texel in 14 bits a side (dsm_list_common.glsl).
    if (request.resolution > kMaxMergeResolution)
      return "a map of more than " + std::to_string(kMaxMergeResolution) +
             " texels a side cannot merge its surfaces";
    failure = allocateMergeQueue(texels);
    if (!failure.empty()) return failure;
  }
  GLuint counts[6] = {};
  for (passes_ = 1; passes_ <= 2; ++passes_) {
    fill(request, casters, textureUnit);
    glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
    glGetNamedBufferSubData(flags_.get(), kCountsOffset, sizeof(counts), counts);
    used_ = counts[request.frame.faceCount - 1];
    if (used_ <= capacity_) break;
    if (passes_ == 2) return "the fragment lists did not hold the map after growing";
    // A quarter more than this map needed, so that a light moved a little does not draw its
    // faces twice again.
    failure = allocateList(used_ + used_ / 4u, byteLimit);
    if (!failure.empty()) return failure;
  }
  // A face that linked no surface keeps no layer: its lists need no resolve.
  std::array<bool, 6> surfaces{};
  for (int face = 0; face < request.frame.faceCount; ++face)
    surfaces[std::size_t(face)] = counts[face] > (face > 0 ? counts[face - 1] : 0u);
  if (guess != nullptr)
    resolveInto(request, *storing, *guess, surfaces);
  else
    resolveInto(request, *counting, MapListLayout{}, surfaces);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  GLuint flags[6 * kMapFaceFlags] = {};
  glGetNamedBufferSubData(flags_.get(), 0, kCountsOffset, flags);
  for (int face = 0; face < request.frame.faceCount; ++face) {
    const GLuint* f = flags + face * kMapFaceFlags;
    MapListFace& out = faces[std::size_t(face)];
    out.heldLayers = {f[0], f[1]};
    out.passingLayers = {f[2], f[3]};
    out.closingLayer = f[4] != 0u;
    out.mergedTexels = f[6];
  }
  return {};
}

void MapFragmentLists::resolveInto(const MapRequest& request, const GlProgram& program,
                                   const MapListLayout& layout, const std::array<bool, 6>& faces) {
  const bool merging = request.mergeOverflow && layout.depthArray != 0;
  if (merging) {
    // No texel queued; the merge's dispatch (groups, 1, 1) of none.
    const GLuint header[4] = {0u, 1u, 1u, 0u};
    glNamedBufferSubData(mergeQueue_.get(), 0, sizeof(header), header);
    glBindBufferBase(GL_SHADER_STORAGE_BUFFER, GLuint(kMapMergeQueueBinding), mergeQueue_.get());
  }
  glUseProgram(program.name());
  program.setInt("uLayers", request.layers);
  program.setInt("uSize", request.resolution);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, GLuint(kFragmentListBinding), list_.get());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, GLuint(kMapFlagsBinding), flags_.get());
  glBindImageTexture(GLuint(kFragmentHeadsUnit), heads_.get(), 0, GL_TRUE, 0, GL_READ_ONLY,
                     GL_R32UI);
  if (layout.depthArray != 0) {
    glBindImageTexture(GLuint(kMapLayerDepthUnit), layout.depthArray, 0, GL_TRUE, 0, GL_WRITE_ONLY,
                       GL_R32F);
    glBindImageTexture(GLuint(kMapLayerVisibilityUnit), layout.visibilityArray, 0, GL_TRUE, 0,
                       GL_WRITE_ONLY, visibilityFormat(request));
  }
  for (int face = 0; face < request.frame.faceCount; ++face) {
    if (!faces[std::size_t(face)]) continue;
    if (layout.depthArray != 0) {
      program.setInt("uFirstLayer", layout.firstLayer[std::size_t(face)]);
      program.setInt("uKept", layout.layers[std::size_t(face)]);
    }
    resolve(request, program, face);
  }
  // The camera pass samples what the resolve wrote, the build reads the flags, the merge
  // writes over the texels it queued, and a second store (the guessed layout did not hold)
  // writes the same texels again.
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT |
                  GL_SHADER_STORAGE_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT |
                  GL_COMMAND_BARRIER_BIT);
  if (merging) merge(request, layout);
}

void MapFragmentLists::merge(const MapRequest& request, const MapListLayout& layout) {
  std::string unused;
  const GlProgram& program = *mergeProgram(request, unused);
  glUseProgram(program.name());
  program.setInt("uLayers", request.layers);
  glUniform1iv(program.location("uFaceFirst"), 6, layout.firstLayer.data());
  // As many groups as the resolve counted into the queue's header.
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, mergeQueue_.get());
  glDispatchComputeIndirect(0);
  glBindBuffer(GL_DISPATCH_INDIRECT_BUFFER, 0);
  glMemoryBarrier(GL_TEXTURE_FETCH_BARRIER_BIT | GL_TEXTURE_UPDATE_BARRIER_BIT |
                  GL_SHADER_STORAGE_BARRIER_BIT | GL_SHADER_IMAGE_ACCESS_BARRIER_BIT);
}

float MapFragmentLists::mergeError() const {
  // The merge's atomics, read back.
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  GLuint flags[6 * kMapFaceFlags] = {};
  glGetNamedBufferSubData(flags_.get(), 0, kCountsOffset, flags);
  float largest = 0.0f;
  for (int face = 0; face < faces_; ++face) {
    float error = 0.0f;
    std::memcpy(&error, &flags[face * kMapFaceFlags + 5], sizeof(float));
    largest = std::max(largest, error);
  }
  return largest;
}

void MapFragmentLists::store(const MapRequest& request, const MapListLayout& layout) {
  std::string unused;
  std::array<bool, 6> faces{};
  for (int face = 0; face < request.frame.faceCount; ++face)
    faces[std::size_t(face)] = layout.layers[std::size_t(face)] > 0;
  resolveInto(request, *resolveProgram(request, true, unused), layout, faces);
}

}  // namespace ivshadow
