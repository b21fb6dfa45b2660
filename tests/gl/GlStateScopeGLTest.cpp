// GlStateScope: what it saves comes back exactly, what it was not told about is neither read
// nor put back, and each group costs the queries it names.
#include "gl/GlHandles.h"
#include "gl/GlProgram.h"
#include "gl/GlStateScope.h"
#include "tests/gl/GlCallCounter.h"
#include "tests/gl/GlContextTest.h"

#include <epoxy/gl.h>

#include <array>

namespace ivshadow::test {
namespace {

class GlStateScopeGLTest : public GlContextTest {};

int integer(GLenum name) {
  GLint value = 0;
  glGetIntegerv(name, &value);
  return value;
}

int integerAt(GLenum name, GLuint index) {
  GLint value = 0;
  glGetIntegeri_v(name, index, &value);
  return value;
}

int boundOn(int unit, GLenum binding) {
  const int active = integer(GL_ACTIVE_TEXTURE);
  glActiveTexture(GL_TEXTURE0 + GLenum(unit));
  const int texture = integer(binding);
  glActiveTexture(GLenum(active));
  return texture;
}

constexpr unsigned int kEverything = GlStateScope::kFramebuffers | GlStateScope::kViewport |
                                     GlStateScope::kProgram | GlStateScope::kVertexArray |
                                     GlStateScope::kStorageBuffers | GlStateScope::kBlendFunction |
                                     GlStateScope::kDepth | GlStateScope::kColourMask |
                                     GlStateScope::kClipControl | GlStateScope::kFragmentTests;

// A state far from GL's defaults in every group, so that a value the scope failed to put back
// cannot pass by equalling a default.
struct FarState {
  GlFramebuffer draw, read;
  GlProgram program;
  GlVertexArray vertexArray;
  GlBuffer first, second, generic;
  GlTexture flat, layered;
};

FarState setFarState() {
  FarState state;
  std::string error;
  state.draw = createFramebuffer();
  state.read = createFramebuffer();
  glBindFramebuffer(GL_DRAW_FRAMEBUFFER, state.draw.get());
  glBindFramebuffer(GL_READ_FRAMEBUFFER, state.read.get());
  glViewport(3, 5, 17, 19);
  state.program =
      GlProgram::link(composeShader("void main() { gl_Position = vec4(0.0); }"),
                      composeShader("out vec4 o; void main() { o = vec4(1.0); }"), error);
  EXPECT_TRUE(state.program) << error;
  glUseProgram(state.program.name());
  state.vertexArray = createVertexArray();
  glBindVertexArray(state.vertexArray.get());
  state.first = createBuffer();
  state.second = createBuffer();
  state.generic = createBuffer();
  glNamedBufferData(state.first.get(), 4, nullptr, GL_STATIC_DRAW);
  glNamedBufferData(state.second.get(), 4, nullptr, GL_STATIC_DRAW);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, state.first.get());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, state.second.get());
  glBindBuffer(GL_SHADER_STORAGE_BUFFER, state.generic.get());
  glBlendFuncSeparate(GL_SRC_COLOR, GL_DST_ALPHA, GL_ONE, GL_ZERO);
  glBlendEquationSeparate(GL_MIN, GL_MAX);
  glDepthFunc(GL_GEQUAL);
  glDepthMask(GL_FALSE);
  glColorMask(GL_TRUE, GL_FALSE, GL_TRUE, GL_FALSE);
  glClipControl(GL_UPPER_LEFT, GL_ZERO_TO_ONE);
  glEnable(GL_BLEND);
  glEnable(GL_CULL_FACE);
  glEnable(GL_SCISSOR_TEST);
  glEnable(GL_CLIP_DISTANCE2);
  glPolygonMode(GL_FRONT, GL_LINE);
  glPolygonMode(GL_BACK, GL_POINT);
  state.flat = createTexture(GL_TEXTURE_2D);
  state.layered = createTexture(GL_TEXTURE_2D_ARRAY);
  glBindTextureUnit(5, state.flat.get());
  glBindTextureUnit(5, state.layered.get());
  glActiveTexture(GL_TEXTURE3);
  return state;
}

// What a pass does in between: every group changed, unit 5 emptied.
void changeEveryGroup(GlStateScope& scope) {
  scope.disableFragmentTests();
  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glViewport(0, 0, 1, 1);
  glUseProgram(0);
  glBindVertexArray(0);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, 0);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, 0);
  glBlendFuncSeparate(GL_ONE, GL_ONE, GL_ONE, GL_ONE);
  glBlendEquation(GL_FUNC_ADD);
  glDepthFunc(GL_LESS);
  glDepthMask(GL_TRUE);
  glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  glClipControl(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE);
  glBindTextureUnit(5, 0);
  glActiveTexture(GL_TEXTURE7);
  EXPECT_FALSE(glIsEnabled(GL_BLEND));
  EXPECT_FALSE(glIsEnabled(GL_CLIP_DISTANCE2));
}

void expectFarState(const FarState& state) {
  EXPECT_EQ(integer(GL_DRAW_FRAMEBUFFER_BINDING), int(state.draw.get()));
  EXPECT_EQ(integer(GL_READ_FRAMEBUFFER_BINDING), int(state.read.get()));
  std::array<GLint, 4> viewport{};
  glGetIntegerv(GL_VIEWPORT, viewport.data());
  EXPECT_EQ(viewport, (std::array<GLint, 4>{3, 5, 17, 19}));
  EXPECT_EQ(integer(GL_CURRENT_PROGRAM), int(state.program.name()));
  EXPECT_EQ(integer(GL_VERTEX_ARRAY_BINDING), int(state.vertexArray.get()));
  EXPECT_EQ(integerAt(GL_SHADER_STORAGE_BUFFER_BINDING, 0), int(state.first.get()));
  EXPECT_EQ(integerAt(GL_SHADER_STORAGE_BUFFER_BINDING, 1), int(state.second.get()));
  EXPECT_EQ(integer(GL_SHADER_STORAGE_BUFFER_BINDING), int(state.generic.get()));
  EXPECT_EQ(integer(GL_BLEND_SRC_RGB), GL_SRC_COLOR);
  EXPECT_EQ(integer(GL_BLEND_DST_RGB), GL_DST_ALPHA);
  EXPECT_EQ(integer(GL_BLEND_SRC_ALPHA), GL_ONE);
  EXPECT_EQ(integer(GL_BLEND_DST_ALPHA), GL_ZERO);
  EXPECT_EQ(integer(GL_BLEND_EQUATION_RGB), GL_MIN);
  EXPECT_EQ(integer(GL_BLEND_EQUATION_ALPHA), GL_MAX);
  EXPECT_EQ(integer(GL_DEPTH_FUNC), GL_GEQUAL);
  GLboolean depthMask = GL_TRUE;
  glGetBooleanv(GL_DEPTH_WRITEMASK, &depthMask);
  EXPECT_EQ(depthMask, GL_FALSE);
  std::array<GLboolean, 4> colourMask{};
  glGetBooleanv(GL_COLOR_WRITEMASK, colourMask.data());
  EXPECT_EQ(colourMask, (std::array<GLboolean, 4>{GL_TRUE, GL_FALSE, GL_TRUE, GL_FALSE}));
  EXPECT_EQ(integer(GL_CLIP_ORIGIN), GL_UPPER_LEFT);
  EXPECT_EQ(integer(GL_CLIP_DEPTH_MODE), GL_ZERO_TO_ONE);
  EXPECT_TRUE(glIsEnabled(GL_BLEND));
  EXPECT_TRUE(glIsEnabled(GL_CULL_FACE));
  EXPECT_TRUE(glIsEnabled(GL_SCISSOR_TEST));
  EXPECT_TRUE(glIsEnabled(GL_CLIP_DISTANCE2));
  EXPECT_FALSE(glIsEnabled(GL_DEPTH_TEST));
  EXPECT_FALSE(glIsEnabled(GL_STENCIL_TEST));
  std::array<GLint, 2> polygonMode{};
  glGetIntegerv(GL_POLYGON_MODE, polygonMode.data());
  EXPECT_EQ(polygonMode, (std::array<GLint, 2>{GL_LINE, GL_POINT}));
  EXPECT_EQ(boundOn(5, GL_TEXTURE_BINDING_2D), int(state.flat.get()));
  EXPECT_EQ(boundOn(5, GL_TEXTURE_BINDING_2D_ARRAY), int(state.layered.get()));
  EXPECT_EQ(integer(GL_ACTIVE_TEXTURE), GL_TEXTURE3);
}

TEST_F(GlStateScopeGLTest, PutsBackEveryNamedGroupAsItFoundIt) {
  const FarState state = setFarState();
  ASSERT_TRUE(state.program);
  {
    GlStateScope scope(kEverything, {{5}, {GL_TEXTURE_2D, GL_TEXTURE_2D_ARRAY}});
    changeEveryGroup(scope);
  }
  expectFarState(state);

  glBindFramebuffer(GL_FRAMEBUFFER, 0);
  glUseProgram(0);
  glBindVertexArray(0);
  glClipControl(GL_LOWER_LEFT, GL_NEGATIVE_ONE_TO_ONE);
}

TEST_F(GlStateScopeGLTest, ReadsAndPutsBackOnlyWhatItIsTold) {
  glViewport(2, 4, 8, 16);
  glDepthFunc(GL_LEQUAL);
  GlCallCounter counter;
  {
    GlStateScope scope(GlStateScope::kViewport);
    glViewport(0, 0, 1, 1);
    glDepthFunc(GL_ALWAYS);
  }
  // One glGetIntegerv(GL_VIEWPORT), nothing else.
  EXPECT_EQ(counter.queries(), 1);
  std::array<GLint, 4> viewport{};
  glGetIntegerv(GL_VIEWPORT, viewport.data());
  EXPECT_EQ(viewport, (std::array<GLint, 4>{2, 4, 8, 16}));
  // Not named, so not saved: the change made inside the scope stays.
  EXPECT_EQ(integer(GL_DEPTH_FUNC), GL_ALWAYS);
  glDepthFunc(GL_LESS);
}

TEST_F(GlStateScopeGLTest, TextureUnitsCostOneQueryPerNamedTarget) {
  const GlTexture a = createTexture(GL_TEXTURE_2D_ARRAY), b = createTexture(GL_TEXTURE_2D_ARRAY);
  const GlTexture flat = createTexture(GL_TEXTURE_2D);
  glBindTextureUnit(4, a.get());
  glBindTextureUnit(6, flat.get());
  glActiveTexture(GL_TEXTURE2);
  GlCallCounter counter;
  {
    GlStateScope scope(0u, {{4, 6}, {GL_TEXTURE_2D_ARRAY}});
    glBindTextureUnit(4, b.get());
    glBindTextureUnit(6, b.get());
  }
  // The active unit, then the array binding of each of the two units.
  EXPECT_EQ(counter.queries(), 3);
  EXPECT_EQ(boundOn(4, GL_TEXTURE_BINDING_2D_ARRAY), int(a.get()));
  EXPECT_EQ(boundOn(6, GL_TEXTURE_BINDING_2D_ARRAY), 0);
  // Binding an array texture leaves the unit's 2D binding alone, so the scope need not save it.
  EXPECT_EQ(boundOn(6, GL_TEXTURE_BINDING_2D), int(flat.get()));
  EXPECT_EQ(integer(GL_ACTIVE_TEXTURE), GL_TEXTURE2);
}

}  // namespace
}  // namespace ivshadow::test
