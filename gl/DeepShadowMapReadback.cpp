#include "gl/DeepShadowMapReadback.h"

#include "gl/GlLimits.h"
#include "gl/PixelStoreScope.h"
#include "gl/ShaderConstants.h"

#include <epoxy/gl.h>

namespace ivshadow {
namespace {

// The texture bound as a 2D array on texture unit `unit`.
GLuint arrayOnUnit(int unit) {
  GLint active = 0;
  glGetIntegerv(GL_ACTIVE_TEXTURE, &active);
  glActiveTexture(GLenum(GL_TEXTURE0 + unit));
  GLint texture = 0;
  glGetIntegerv(GL_TEXTURE_BINDING_2D_ARRAY, &texture);
  glActiveTexture(GLenum(active));
  return GLuint(texture);
}

GLint levelParameter(GLuint texture, GLenum name) {
  GLint value = 0;
  glGetTextureLevelParameteriv(texture, 0, name, &value);
  return value;
}

}  // namespace

bool readBoundMapLayer(int slot, int layer, MapLayerReadback& out, std::string& whyNot) {
  GLint program = 0;
  glGetIntegerv(GL_CURRENT_PROGRAM, &program);
  if (program == 0) {
    whyNot = "no deep shadow group is drawing (is it active?)";
    return false;
  }
  // The units ShadingUniforms gives the slot's samplers, from the context's unit count: no
  // uniform of the program is looked up.
  const int units = glInteger(GL_MAX_TEXTURE_IMAGE_UNITS);
  const bool inRange = slot >= 0 && slot < kMaxGlLights;
  const GLuint depth = inRange ? arrayOnUnit(mapDepthUnit(units, slot)) : 0;
  const GLuint visibility = inRange ? arrayOnUnit(mapVisibilityUnit(units, slot)) : 0;
  if (depth == 0 || visibility == 0) {
    whyNot = "no map is bound for light " + std::to_string(slot);
    return false;
  }
  return readMapLayer(depth, visibility, layer, out, whyNot);
}

bool readMapLayer(unsigned int depth, unsigned int visibility, int layer, MapLayerReadback& out,
                  std::string& whyNot) {
  const GLint size = levelParameter(depth, GL_TEXTURE_WIDTH);
  const GLint layers = levelParameter(depth, GL_TEXTURE_DEPTH);
  if (layer < 0 || layer >= layers || size <= 0) {
    whyNot =
        "the map holds " + std::to_string(layers) + " layers, not layer " + std::to_string(layer);
    return false;
  }
  const GLint format = levelParameter(visibility, GL_TEXTURE_INTERNAL_FORMAT);
  const bool coloured = format == GL_RGBA16F || format == GL_RGBA32F;
  out.size = size;
  out.channels = coloured ? 3 : 1;
  const std::size_t texels = std::size_t(size) * std::size_t(size);
  out.depth.assign(texels, 0.0f);
  std::vector<float> rgba(coloured ? texels * 4 : texels);

  {
    const PixelStoreScope pixelStore;
    glGetTextureSubImage(depth, 0, 0, 0, layer, size, size, 1, GL_RED, GL_FLOAT,
                         GLsizei(texels * sizeof(float)), out.depth.data());
    glGetTextureSubImage(visibility, 0, 0, 0, layer, size, size, 1, coloured ? GL_RGBA : GL_RED,
                         GL_FLOAT, GLsizei(rgba.size() * sizeof(float)), rgba.data());
  }

  if (coloured) {
    out.visibility.resize(texels * 3);
    for (std::size_t i = 0; i < texels; ++i)
      for (std::size_t c = 0; c < 3; ++c) out.visibility[i * 3 + c] = rgba[i * 4 + c];
  } else {
    out.visibility = std::move(rgba);
  }
  return true;
}

}  // namespace ivshadow
