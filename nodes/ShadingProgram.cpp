#include "nodes/ShadingProgram.h"

#include "GlslSources.h"
#include "callbacks/GlProgram.h"

#include <Inventor/nodes/SoFragmentShader.h>
#include <Inventor/nodes/SoShaderParameter.h>
#include <Inventor/nodes/SoShaderProgram.h>
#include <Inventor/nodes/SoVertexShader.h>

namespace ivshadow {

ShadingProgram::ShadingProgram(bool peelPasses) : program_(new SoShaderProgram) {
  auto* vertex = new SoVertexShader;
  vertex->sourceType = SoShaderObject::GLSL_PROGRAM;
  vertex->sourceProgram = composeShader(glsl::kShadingVert).c_str();
  auto* fragment = new SoFragmentShader;
  fragment->sourceType = SoShaderObject::GLSL_PROGRAM;
  fragment->sourceProgram =
      composeShader(glsl::kShadingFrag, peelPasses ? "#define IVSHADOW_PEEL_PASSES\n" : "").c_str();
  // Coin fills these in from its state whenever they change (SoShaderObject::coin_*).
  for (const char* name : {"coin_light_model", "coin_two_sided_lighting", "coin_texunit0_model"}) {
    auto* parameter = new SoShaderParameter1i;
    parameter->name = name;
    fragment->parameter.addNode(parameter);
  }
  program_->shaderObject.addNode(vertex);
  program_->shaderObject.addNode(fragment);
}

}  // namespace ivshadow
