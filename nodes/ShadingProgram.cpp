#include "nodes/ShadingProgram.h"

#include "GlslSources.h"
#include "gl/GlProgram.h"
#include "gl/ShadingUniforms.h"
#include "gl/UniformLocations.h"
#include "nodes/ShadowGroupElement.h"

#include <Inventor/actions/SoGLRenderAction.h>
#include <Inventor/elements/SoGLCacheContextElement.h>
#include <Inventor/elements/SoGLLazyElement.h>
#include <Inventor/errors/SoDebugError.h>
#include <Inventor/nodes/SoFragmentShader.h>
#include <Inventor/nodes/SoShaderParameter.h>
#include <Inventor/nodes/SoShaderProgram.h>
#include <Inventor/nodes/SoVertexShader.h>

#include <mutex>
#include <string>
#include <vector>

namespace ivshadow {
namespace {

struct VariantSource {
  std::string fragment;
  const char* defines;
  // The coin_* uniforms the variant uses: Coin warns about a parameter a program lacks.
  std::vector<const char*> coinParameters;
};

VariantSource sourceOf(ShadingVariant variant) {
  const std::string lit = std::string(glsl::kBounceCommonGlsl) + glsl::kLightingGlsl;
  const std::vector<const char*> lighting = {"coin_light_model", "coin_two_sided_lighting",
                                             "coin_texunit0_model"};
  const std::vector<const char*> texture = {"coin_texunit0_model"};
  switch (variant) {
    case ShadingVariant::Shade:
      return {lit + glsl::kShadingFrag, "", lighting};
    case ShadingVariant::OpaqueOnly:
      return {lit + glsl::kShadingFrag, "#define IVSHADOW_OPAQUE_ONLY\n", lighting};
    case ShadingVariant::PeelInit:
      // The first pass only records depths: no fragment is lit.
      return {lit + glsl::kPeelFrag, "#define IVSHADOW_PEEL_INIT\n", texture};
    case ShadingVariant::PeelFrontToBack:
      return {lit + glsl::kPeelFrag, "", lighting};
    case ShadingVariant::PeelDual:
      return {lit + glsl::kPeelFrag, "#define IVSHADOW_PEEL_DUAL\n", lighting};
    case ShadingVariant::CaptureOpaque:
      return {glsl::kCaptureFrag, "#define IVSHADOW_CAPTURE_OPAQUE\n", texture};
    case ShadingVariant::CaptureTransparent:
      return {glsl::kCaptureFrag, "", texture};
    case ShadingVariant::FragmentList:
      return {lit + glsl::kFragmentListCommonGlsl + glsl::kFragmentListFrag, "", lighting};
  }
  return {};
}

// Whether the variant's fragment program lights anything (and so compiles ShadingFeatures in):
// the captures record colours and depths, the first peel pass depths only.
bool lights(ShadingVariant variant) {
  return variant != ShadingVariant::CaptureOpaque &&
         variant != ShadingVariant::CaptureTransparent && variant != ShadingVariant::PeelInit;
}

// Making a variant sets fields (its sources), and so does binding one (Coin fills the coin_*
// parameters in from the state): each notifies through Coin's notification counter and sensor
// queue, which a Coin built without COIN_THREADSAFE (Debian's) does not guard. Contexts
// rendering on several threads make and bind the plugin's programs one at a time.
std::mutex& programFieldsMutex() {
  static std::mutex mutex;
  return mutex;
}

// Says once in the process which uniforms the plugin sets but no variant declares: a misspelt
// name would be -1 in every program, its value never set and nothing said.
void warnUndeclaredUniforms() {
  static const bool said = [] {
    for (std::string_view name : ShadingLocations::undeclared(ShadingProgram::declarations()))
      SoDebugError::postWarning("ShadingProgram",
                                "no shading program declares the uniform %s: it is never set",
                                std::string(name).c_str());
    return true;
  }();
  (void)said;
}

}  // namespace

ShadingProgram::ShadingProgram() = default;
ShadingProgram::~ShadingProgram() = default;

std::string ShadingFeatures::defines() const {
  std::string text;
  if (maps) text += "#define IVSHADOW_WITH_MAPS\n";
  if (rays) text += "#define IVSHADOW_WITH_RAYS\n";
  // Maps with neither lookup named: both, so that every map is still read.
  const bool anyLookup = nearest || filtered;
  if (nearest || (maps && !anyLookup)) text += "#define IVSHADOW_WITH_NEAREST_TEXEL\n";
  if (filtered || (maps && !anyLookup)) text += "#define IVSHADOW_WITH_FILTERED_MAPS\n";
  // Maps of neither kind named: both.
  if (deep || (maps && !opacity)) text += "#define IVSHADOW_WITH_DEEP_MAPS\n";
  if (opacity || (maps && !deep)) text += "#define IVSHADOW_WITH_OPACITY_MAPS\n";
  if (fog) text += "#define IVSHADOW_WITH_FOG\n";
  if (bounce) text += "#define IVSHADOW_WITH_BOUNCE\n";
  return text;
}

std::string ShadingProgram::declarations() {
  std::string text = composeShader(glsl::kShadingVert);
  for (int variant = 0; variant <= int(ShadingVariant::FragmentList); ++variant)
    text += composeShader(sourceOf(ShadingVariant(variant)).fragment);
  return text;
}

int ShadingProgram::keyOf(ShadingVariant variant, const ShadingFeatures& features) {
  return int(variant) * ShadingFeatures::kKeys + features.key();
}

SoShaderProgram* ShadingProgram::node(ShadingVariant variant, const ShadingFeatures& features) {
  CoinRef<SoShaderProgram>& program = nodes_[keyOf(variant, features)];
  if (program) return program.get();
  const VariantSource source = sourceOf(variant);
  program = CoinRef<SoShaderProgram>(new SoShaderProgram);
  auto* vertex = new SoVertexShader;
  vertex->sourceType = SoShaderObject::GLSL_PROGRAM;
  vertex->sourceProgram = composeShader(glsl::kShadingVert).c_str();
  auto* fragment = new SoFragmentShader;
  fragment->sourceType = SoShaderObject::GLSL_PROGRAM;
  fragment->sourceProgram =
      composeShader(source.fragment, source.defines + features.defines()).c_str();
  // Coin fills these in from its state whenever they change (SoShaderObject::coin_*).
  for (const char* name : source.coinParameters) {
    auto* parameter = new SoShaderParameter1i;
    parameter->name = name;
    fragment->parameter.addNode(parameter);
  }
  program->shaderObject.addNode(vertex);
  program->shaderObject.addNode(fragment);
  return program.get();
}

const ShadingLocations* ShadingProgram::bind(SoGLRenderAction* action, ShadingVariant variant,
                                             const ShadingFeatures& requested) {
  const ShadingFeatures features = lights(variant) ? requested : ShadingFeatures{};
  {
    const std::lock_guard<std::mutex> lock(programFieldsMutex());
    node(variant, features)->GLRender(action);
  }
  const unsigned int program = currentProgram();
  if (program == 0) return nullptr;
  ShadowGroupElement::setProgram(action->getState(), int(variant));
  // Coin fills in coin_light_model and coin_two_sided_lighting when the program is bound (from
  // the state here, above the group's shape hints) and afterwards only when the GL state it
  // last sent changes. A frame (or Coin's delayed pass) that begins with two-sided lighting
  // already on in GL therefore left the program's uniform at 0 for every shape below, and
  // back faces went unlit. Forgetting what was sent makes Coin send both again, and update
  // this program's uniforms with them, at the next shape.
  SoGLLazyElement::getInstance(action->getState())
      ->reset(action->getState(), SoLazyElement::LIGHT_MODEL_MASK | SoLazyElement::TWOSIDE_MASK);
  Linked& context = linked(action->getState());
  const int key = keyOf(variant, features);
  ShadingLocations& locations = context.locations[key];
  // Coin links a variant once per context; a new name means it linked it anew, with every
  // uniform at 0.
  if (locations.program != program) {
    warnUndeclaredUniforms();
    locations = ShadingLocations(UniformLocations(program));
    context.texGen[key] = TexGenModes{};
  }
  return &locations;
}

ShadingProgram::Linked& ShadingProgram::linked(SoState* state) {
  return *linked_.get(SoGLCacheContextElement::get(state),
                      [] { return std::make_unique<Linked>(); });
}

const ShadingLocations* ShadingProgram::current(SoState* state) {
  const unsigned int program = currentProgram();
  if (program == 0) return nullptr;
  for (const auto& [key, locations] : linked(state).locations)
    if (locations.program == program) return &locations;
  return nullptr;
}

void ShadingProgram::sendTexGen(SoState* state, const TexGenModes& modes) {
  Linked& context = linked(state);
  for (const auto& [key, locations] : context.locations) {
    if (locations.program == 0 || context.texGen[key] == modes) continue;
    setTexGenModes(locations, modes);
    context.texGen[key] = modes;
  }
}

bool ShadingProgram::anyTexGen(SoState* state) {
  for (const auto& [key, modes] : linked(state).texGen)
    if (modes != TexGenModes{}) return true;
  return false;
}

}  // namespace ivshadow
