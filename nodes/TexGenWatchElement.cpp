#include "nodes/TexGenWatchElement.h"

#include "nodes/GroupShading.h"
#include "nodes/ShadowGroupElement.h"

#include <Inventor/elements/SoCacheElement.h>
#include <Inventor/misc/SoState.h>

namespace ivshadow {

SO_ELEMENT_SOURCE(TexGenWatchElement);

void TexGenWatchElement::initClass() {
  if (getClassTypeId() != SoType::badType()) return;
  SO_ELEMENT_INIT_CLASS(TexGenWatchElement, inherited);
  SoType::overrideType(SoGLMultiTextureCoordinateElement::getClassTypeId(),
                       &TexGenWatchElement::createInstance);
}

TexGenWatchElement::~TexGenWatchElement() = default;

void TexGenWatchElement::init(SoState* state) {
  inherited::init(state);
  state_ = state;
  generated_ = false;
}

void TexGenWatchElement::push(SoState* state) {
  inherited::push(state);
  state_ = state;
  // The element below may be Coin's own, in a state made before this one was registered.
  const SoElement* below = getNextInStack();
  generated_ = below->getTypeId().isDerivedFrom(getClassTypeId()) &&
               static_cast<const TexGenWatchElement*>(below)->generated_;
}

void TexGenWatchElement::pop(SoState* state, const SoElement* prevTopElement) {
  inherited::pop(state, prevTopElement);
  changed(state, generated_);
}

void TexGenWatchElement::setElt(const int unit, SoTexCoordTexgenCB* func, void* data) {
  inherited::setElt(unit, func, data);
  if (unit != 0) return;
  generated_ = func != nullptr;
  // A render cache below a group would replay the function's GL state without this element
  // seeing it, and the programs would keep the modes of before: no cache records one.
  if (state_ != nullptr && state_->isElementEnabled(ShadowGroupElement::getClassStackIndex()) &&
      ShadowGroupElement::shading(state_) != nullptr)
    SoCacheElement::invalidate(state_);
  changed(state_, generated_);
}

bool TexGenWatchElement::generatesTexCoords(SoState* state) {
  const SoElement* element = getConstElement(state, classStackIndex);
  return element->getTypeId().isDerivedFrom(getClassTypeId()) &&
         static_cast<const TexGenWatchElement*>(element)->generated_;
}

void TexGenWatchElement::changed(SoState* state, bool generated) {
  // Actions that draw with GL but never enabled the plugin's element have no group below.
  if (state == nullptr || !state->isElementEnabled(ShadowGroupElement::getClassStackIndex()))
    return;
  if (GroupShading* shading = ShadowGroupElement::shading(state))
    shading->syncTexGen(state, generated);
}

}  // namespace ivshadow
