// A deep shadow map's build against one plain cube shadow-map pass over the same casters, in
// one run: the map from fragment lists (one draw per face, then the sort), the same map
// peeled (one draw per layer), and a depth-only draw of the casters into each of the six
// faces, which is what an opaque shadow map costs. The casters are the sphere field of
// bench/BenchScenes.cpp, the light its lamp, the cube that of the group's map (gl/
// MapFrame). Run: build/bin/ivshadow_bench --benchmark_filter=MapBuildMethods. Times are wall
// clock, the GL finished before and after.
#include "BenchScenes.h"
#include "gl/DeepShadowPass.h"
#include "gl/GlHandles.h"
#include "gl/GlProgram.h"
#include "headless/OffscreenRenderer.h"
#include "ivshadow/IvShadowInit.h"
#include "ivshadow/SoDeepShadowLight.h"
#include "scene/SceneTriangles.h"

#include <Inventor/nodes/SoSeparator.h>
#include <benchmark/benchmark.h>
#include <epoxy/gl.h>
#include <glm/glm.hpp>
#include <glm/gtc/type_ptr.hpp>

#include <chrono>
#include <cstddef>
#include <memory>
#include <string>

namespace {

constexpr int kResolution = 512;

// The lists truncate past maxLayers, as the peel does; MergedLists merge (layerOverflow MERGE,
// the lights' default), which only texels with more surfaces than layers pay for.
enum class Build { PlainCube = 0, Peeled = 1, FragmentLists = 2, MergedLists = 3 };

double finishedMs() {
  glFinish();
  return std::chrono::duration<double, std::milli>(
             std::chrono::steady_clock::now().time_since_epoch())
      .count();
}

// The baseline: the casters' positions drawn six times into a depth texture with an empty
// fragment program, as any cube shadow map of opaque casters is drawn.
class PlainCubePass {
 public:
  PlainCubePass(const ivshadow::SceneTriangles& casters, std::string& error) {
    program_ = ivshadow::GlProgram::link(
        "#version 450\nlayout(location = 0) in vec3 aPosition;\nuniform mat4 uViewProjection;\n"
        "void main() { gl_Position = uViewProjection * vec4(aPosition, 1.0); }\n",
        "#version 450\nvoid main() {}\n", error);
    vertices_ = GLsizei(casters.vertices.size());
    buffer_ = ivshadow::createBuffer();
    glNamedBufferData(buffer_.get(),
                      GLsizeiptr(casters.vertices.size() * sizeof(ivshadow::TriangleVertex)),
                      casters.vertices.data(), GL_STATIC_DRAW);
    vertexArray_ = ivshadow::createVertexArray();
    const GLuint vao = vertexArray_.get();
    glVertexArrayVertexBuffer(vao, 0, buffer_.get(), 0, sizeof(ivshadow::TriangleVertex));
    glEnableVertexArrayAttrib(vao, 0);
    glVertexArrayAttribFormat(vao, 0, 3, GL_FLOAT, GL_FALSE,
                              offsetof(ivshadow::TriangleVertex, position));
    glVertexArrayAttribBinding(vao, 0, 0);
    depth_ = ivshadow::createTarget2D(GL_DEPTH_COMPONENT32F, kResolution, kResolution);
    framebuffer_ = ivshadow::createFramebuffer();
    glNamedFramebufferTexture(framebuffer_.get(), GL_DEPTH_ATTACHMENT, depth_.get(), 0);
    glNamedFramebufferDrawBuffer(framebuffer_.get(), GL_NONE);
  }
  void draw(const ivshadow::MapFrame& frame) const {
    glBindFramebuffer(GL_FRAMEBUFFER, framebuffer_.get());
    glViewport(0, 0, kResolution, kResolution);
    // The map's reversed depth: near at 1.
    glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_GREATER);
    glDepthMask(GL_TRUE);
    glUseProgram(program_.name());
    glBindVertexArray(vertexArray_.get());
    for (int face = 0; face < frame.faceCount; ++face) {
      const float farthest = 0.0f;
      glClearNamedFramebufferfv(framebuffer_.get(), GL_DEPTH, 0, &farthest);
      program_.setMat4("uViewProjection",
                       glm::value_ptr(frame.faces[std::size_t(face)].viewProjection));
      glDrawArrays(GL_TRIANGLES, 0, vertices_);
    }
  }

 private:
  ivshadow::GlProgram program_;
  ivshadow::GlBuffer buffer_;
  ivshadow::GlVertexArray vertexArray_;
  ivshadow::GlTexture depth_;
  ivshadow::GlFramebuffer framebuffer_;
  GLsizei vertices_ = 0;
};

// Args: triangles, maxLayers, Build.
void MapBuildMethods(benchmark::State& state) {
  ivshadow::init();
  std::string error;
  auto renderer = ivshadow::OffscreenRenderer::create(64, 64, error);
  if (!renderer) {
    state.SkipWithError(error.c_str());
    return;
  }
  SoSeparator* root = ivshadow::bench::sphereField(int(state.range(0)), true,
                                                   ivshadow::bench::Shadows::DeepShadowGroup,
                                                   kResolution, kResolution);
  const auto* lamp = static_cast<SoDeepShadowLight*>(SoNode::getByName("Lamp"));
  const SbVec3f at = lamp->location.getValue();
  const ivshadow::SceneTriangles casters = ivshadow::extractShadowCasters(root);
  root->unref();
  ivshadow::MapRequest request;
  // Near and far as the group fits them: the casters' box seen from the light.
  request.frame = ivshadow::cubeFrame({at[0], at[1], at[2]}, 0.05f, 24.0f);
  request.resolution = kResolution;
  request.layers = int(state.range(1));
  request.coloured = true;
  request.colourModel = ivshadow::ShadowColourModel::Saturate;
  const auto build = Build(state.range(2));
  request.fragmentLists = build == Build::FragmentLists || build == Build::MergedLists;
  request.mergeOverflow = build == Build::MergedLists;

  std::unique_ptr<ivshadow::DeepShadowPass> pass;
  std::unique_ptr<PlainCubePass> plain;
  if (build == Build::PlainCube) {
    plain = std::make_unique<PlainCubePass>(casters, error);
  } else {
    pass = ivshadow::DeepShadowPass::create(error);
    if (pass) pass->uploadCasters(casters);
  }
  if (!pass && !plain) {
    state.SkipWithError(error.c_str());
    return;
  }
  ivshadow::MapBuildResult built;
  const auto once = [&] {
    if (plain)
      plain->draw(request.frame);
    else
      built = pass->build(0, request);
  };
  once();  // links the programs, and grows the lists to what the map needs
  for (auto _ : state) {
    const double start = finishedMs();
    once();
    state.SetIterationTime((finishedMs() - start) * 1e-3);
  }
  int layers = 0, passes = 0;
  for (int face = 0; face < 6; ++face) {
    layers += built.layersUsed[std::size_t(face)];
    passes += built.passes[std::size_t(face)];
  }
  state.counters["triangles"] = double(casters.triangleCount());
  if (pass) {
    state.counters["layers"] = layers;
    state.counters["draws"] = passes;
    state.counters["peak_MB"] = double(pass->mapPeakBytes(0)) / 1048576.0;
    // The lists' sorts of the last build: 1 where the layout of the one before held.
    if (built.fragmentLists) state.counters["sorts"] = built.listSorts;
    if (build == Build::MergedLists) state.counters["merged_texels"] = double(built.mergedTexels);
  } else {
    state.counters["draws"] = 6;
  }
  state.SetLabel(build == Build::PlainCube       ? "plain cube pass"
                 : build == Build::Peeled        ? "peeled"
                 : build == Build::FragmentLists ? "fragment lists"
                                                 : "fragment lists, merged");
  pass.reset();
  plain.reset();
}

BENCHMARK(MapBuildMethods)
    ->ArgsProduct({{10000, 100000}, {1, 4, 8}, {0, 1, 2, 3}})
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond)
    ->Iterations(5);

}  // namespace
