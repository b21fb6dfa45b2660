#include "scene/InheritedState.h"

#include <Inventor/annex/FXViz/elements/SoShadowStyleElement.h>
#include <Inventor/elements/SoComplexityElement.h>
#include <Inventor/elements/SoComplexityTypeElement.h>
#include <Inventor/elements/SoCoordinateElement.h>
#include <Inventor/elements/SoDrawStyleElement.h>
#include <Inventor/elements/SoFontNameElement.h>
#include <Inventor/elements/SoFontSizeElement.h>
#include <Inventor/elements/SoLazyElement.h>
#include <Inventor/elements/SoMaterialBindingElement.h>
#include <Inventor/elements/SoMultiTextureCoordinateElement.h>
#include <Inventor/elements/SoMultiTextureEnabledElement.h>
#include <Inventor/elements/SoMultiTextureImageElement.h>
#include <Inventor/elements/SoMultiTextureMatrixElement.h>
#include <Inventor/elements/SoOverrideElement.h>
#include <Inventor/elements/SoProfileCoordinateElement.h>
#include <Inventor/elements/SoProfileElement.h>
#include <Inventor/elements/SoShapeHintsElement.h>
#include <Inventor/elements/SoSwitchElement.h>
#include <Inventor/elements/SoTextureCoordinateBindingElement.h>
#include <Inventor/elements/SoTextureQualityElement.h>
#include <Inventor/elements/SoTextureUnitElement.h>
#include <Inventor/elements/SoUnitsElement.h>
#include <Inventor/misc/SoState.h>

namespace ivshadow {
namespace {

// The elements SoShape::generatePrimitives and the caster extraction read. Each is matched
// as Coin's render caches match it: by value (complexity, draw style, units, ...) or by the
// id of the node that set it (coordinates, textures, profiles, ...), which changes whenever
// that node changes.
std::vector<int> matchedElements() {
  return {SoComplexityElement::getClassStackIndex(),
          SoComplexityTypeElement::getClassStackIndex(),
          SoDrawStyleElement::getClassStackIndex(),
          SoShapeHintsElement::getClassStackIndex(),
          SoUnitsElement::getClassStackIndex(),
          SoShadowStyleElement::getClassStackIndex(),
          SoTextureQualityElement::getClassStackIndex(),
          SoTextureUnitElement::getClassStackIndex(),
          SoMultiTextureImageElement::getClassStackIndex(),
          SoMultiTextureEnabledElement::getClassStackIndex(),
          SoMultiTextureCoordinateElement::getClassStackIndex(),
          SoMultiTextureMatrixElement::getClassStackIndex(),
          SoTextureCoordinateBindingElement::getClassStackIndex(),
          SoCoordinateElement::getClassStackIndex(),
          SoMaterialBindingElement::getClassStackIndex(),
          SoProfileElement::getClassStackIndex(),
          SoProfileCoordinateElement::getClassStackIndex(),
          SoFontNameElement::getClassStackIndex(),
          SoFontSizeElement::getClassStackIndex(),
          SoSwitchElement::getClassStackIndex(),
          SoOverrideElement::getClassStackIndex()};
}

void materialValues(SoState* state, std::vector<float>& colours,
                    std::vector<std::uint32_t>& packed) {
  colours.clear();
  packed.clear();
  const SoLazyElement* lazy = SoLazyElement::getInstance(state);
  if (lazy->isPacked()) {
    const std::uint32_t* values = SoLazyElement::getPackedColors(state);
    packed.assign(values, values + lazy->getNumDiffuse());
    return;
  }
  for (int i = 0; i < lazy->getNumDiffuse(); ++i) {
    const SbColor& diffuse = SoLazyElement::getDiffuse(state, i);
    colours.insert(colours.end(), {diffuse[0], diffuse[1], diffuse[2]});
  }
  for (int i = 0; i < lazy->getNumTransparencies(); ++i)
    colours.push_back(SoLazyElement::getTransparency(state, i));
}

}  // namespace

InheritedState::InheritedState() = default;
InheritedState::~InheritedState() = default;
InheritedState::InheritedState(InheritedState&& other) noexcept = default;
InheritedState& InheritedState::operator=(InheritedState&& other) noexcept = default;

InheritedState InheritedState::capture(SoState* state) {
  InheritedState result;
  for (int index : matchedElements()) {
    if (!state->isElementEnabled(index)) continue;
    ElementCopy copy;
    copy.stackIndex = index;
    copy.match.reset(state->getConstElement(index)->copyMatchInfo());
    result.elements_.push_back(std::move(copy));
  }
  materialValues(state, result.colours_, result.packed_);
  result.captured_ = true;
  return result;
}

bool InheritedState::matches(SoState* state) const {
  if (!captured_) return false;
  for (const ElementCopy& copy : elements_)
    if (!state->isElementEnabled(copy.stackIndex) ||
        !copy.match->matches(state->getConstElement(copy.stackIndex)))
      return false;
  // Reused buffers: this runs every frame.
  thread_local std::vector<float> colours;
  thread_local std::vector<std::uint32_t> packed;
  materialValues(state, colours, packed);
  return colours == colours_ && packed == packed_;
}

}  // namespace ivshadow
