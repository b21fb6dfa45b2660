#pragma once

#include "gl/GlHandles.h"

#include <string>
#include <vector>

namespace ivshadow {

class GlProgram;
struct SceneTriangles;

// The shadow casters of one group in GPU memory: one vertex buffer (position, colour and
// opacity, texture coordinate) and the textures, drawn batch by batch.
class CasterBuffers {
 public:
  // Empty when the vertex buffer and textures were allocated; else what GL said (then draw()
  // draws nothing).
  std::string upload(const SceneTriangles& triangles);
  // Draws every batch with `program` current, binding each batch's texture to `textureUnit`
  // and setting the program's uTexture* uniforms.
  void draw(const GlProgram& program, int textureUnit) const;

 private:
  struct Batch {
    int texture;
    int firstVertex;
    int vertexCount;
  };
  struct Texture {
    GlTexture name;
    int model;
    float blendColour[3];
  };
  GlVertexArray vertexArray_;
  GlBuffer vertexBuffer_;
  std::vector<Batch> batches_;
  std::vector<Texture> textures_;
};

}  // namespace ivshadow
