#include "gl/CasterBuffers.h"

#include "gl/GlAllocationCheck.h"
#include "gl/GlProgram.h"
#include "scene/SceneTriangles.h"

#include <epoxy/gl.h>

#include <cstddef>

namespace ivshadow {

std::string CasterBuffers::upload(const SceneTriangles& triangles) {
  clearGlErrors();
  if (!vertexArray_) {
    vertexArray_ = createVertexArray();
    vertexBuffer_ = createBuffer();
    labelGlObject(GL_VERTEX_ARRAY, vertexArray_.get(), "map casters");
    labelGlObject(GL_BUFFER, vertexBuffer_.get(), "map casters' vertices");
    const GLuint vao = vertexArray_.get();
    glVertexArrayVertexBuffer(vao, 0, vertexBuffer_.get(), 0, sizeof(TriangleVertex));
    const GLuint offsets[3] = {offsetof(TriangleVertex, position), offsetof(TriangleVertex, colour),
                               offsetof(TriangleVertex, texCoord)};
    const GLint sizes[3] = {3, 4, 2};
    for (GLuint attribute = 0; attribute < 3; ++attribute) {
      glEnableVertexArrayAttrib(vao, attribute);
      glVertexArrayAttribFormat(vao, attribute, sizes[attribute], GL_FLOAT, GL_FALSE,
                                offsets[attribute]);
      glVertexArrayAttribBinding(vao, attribute, 0);
    }
  }
  const std::size_t size = triangles.vertices.size() * sizeof(TriangleVertex);
  // Immutable storage would need a new buffer per upload; casters change rarely, so a
  // mutable buffer that is reallocated in place is enough.
  glNamedBufferData(vertexBuffer_.get(), GLsizeiptr(size > 0 ? size : 1),
                    size > 0 ? triangles.vertices.data() : nullptr, GL_STATIC_DRAW);
  const std::string buffer = glAllocationError(GlAllocation::Buffer);
  batches_.clear();
  textures_.clear();
  if (!buffer.empty()) return "GL could not allocate the casters' vertex buffer (" + buffer + ")";
  for (const TriangleBatch& batch : triangles.batches)
    batches_.push_back({batch.texture, int(batch.firstVertex), int(batch.vertexCount)});

  for (const TextureImage& image : triangles.textures) {
    Texture texture{createTexture(GL_TEXTURE_2D),
                    image.model,
                    {image.blendColour[0], image.blendColour[1], image.blendColour[2]}};
    const GLuint name = texture.name.get();
    glTextureStorage2D(name, 1, GL_RGBA8, image.width, image.height);
    GLint alignment = 4;
    glGetIntegerv(GL_UNPACK_ALIGNMENT, &alignment);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTextureSubImage2D(name, 0, 0, 0, image.width, image.height, GL_RGBA, GL_UNSIGNED_BYTE,
                        image.rgba.data());
    glPixelStorei(GL_UNPACK_ALIGNMENT, alignment);
    const GLint filter = image.nearest ? GL_NEAREST : GL_LINEAR;
    glTextureParameteri(name, GL_TEXTURE_MIN_FILTER, filter);
    glTextureParameteri(name, GL_TEXTURE_MAG_FILTER, filter);
    glTextureParameteri(name, GL_TEXTURE_WRAP_S, image.repeatS ? GL_REPEAT : GL_CLAMP_TO_EDGE);
    glTextureParameteri(name, GL_TEXTURE_WRAP_T, image.repeatT ? GL_REPEAT : GL_CLAMP_TO_EDGE);
    textures_.push_back(std::move(texture));
  }
  // Asked only when there are textures: an allocation that made none cannot have failed.
  const std::string textures =
      textures_.empty() ? std::string() : glAllocationError(GlAllocation::Texture);
  if (textures.empty()) return {};
  batches_.clear();
  textures_.clear();
  return "GL could not allocate the casters' textures (" + textures + ")";
}

void CasterBuffers::draw(const GlProgram& program, int textureUnit) const {
  if (!vertexArray_) return;
  glBindVertexArray(vertexArray_.get());
  program.setInt("uTexture", textureUnit);
  for (const Batch& batch : batches_) {
    if (batch.texture >= 0) {
      const Texture& texture = textures_[std::size_t(batch.texture)];
      glBindTextureUnit(GLuint(textureUnit), texture.name.get());
      program.setInt("uTextureModel", texture.model);
      program.setVec3("uTextureBlendColour", texture.blendColour);
    } else {
      program.setInt("uTextureModel", 0);
    }
    // Triangles are numbered across the batches, so that a program can tell two of them
    // apart where they lie on each other (dsm_build.frag).
    program.setInt("uFirstTriangle", batch.firstVertex / 3);
    glDrawArrays(GL_TRIANGLES, batch.firstVertex, batch.vertexCount);
  }
}

}  // namespace ivshadow
