#include "nodes/ShadowGroupElement.h"

#include "nodes/MaterialSyncElement.h"
#include "nodes/TexGenWatchElement.h"

#include <Inventor/actions/SoGLRenderAction.h>
#include <Inventor/misc/SoState.h>

namespace ivshadow {

SO_ELEMENT_SOURCE(ShadowGroupElement);

void ShadowGroupElement::initClass() {
  if (getClassTypeId() != SoType::badType()) return;
  SO_ELEMENT_INIT_CLASS(ShadowGroupElement, inherited);
  SO_ENABLE(SoGLRenderAction, ShadowGroupElement);
  // The shapes below a group or a peeling separator need it (TexGenWatchElement.h).
  TexGenWatchElement::initClass();
  // So does the material they are drawn with (MaterialSyncElement.h).
  MaterialSyncElement::initClass();
}

ShadowGroupElement::~ShadowGroupElement() = default;

void ShadowGroupElement::init(SoState* state) {
  inherited::init(state);
  group_ = nullptr;
  shading_ = nullptr;
  capturing_ = false;
  peeling_ = false;
  program_ = -1;
}

void ShadowGroupElement::push(SoState* state) {
  inherited::push(state);
  const auto* previous = static_cast<const ShadowGroupElement*>(getNextInStack());
  group_ = previous->group_;
  shading_ = previous->shading_;
  capturing_ = previous->capturing_;
  peeling_ = previous->peeling_;
  program_ = previous->program_;
}

SbBool ShadowGroupElement::matches(const SoElement* element) const {
  const auto* other = static_cast<const ShadowGroupElement*>(element);
  return other->group_ == group_ && other->shading_ == shading_ &&
         other->capturing_ == capturing_ && other->peeling_ == peeling_ &&
         other->program_ == program_;
}

SoElement* ShadowGroupElement::copyMatchInfo() const {
  auto* copy = static_cast<ShadowGroupElement*>(getTypeId().createInstance());
  copy->group_ = group_;
  copy->shading_ = shading_;
  copy->capturing_ = capturing_;
  copy->peeling_ = peeling_;
  copy->program_ = program_;
  return copy;
}

void ShadowGroupElement::setActiveGroup(SoState* state, GroupShading* group) {
  static_cast<ShadowGroupElement*>(getElement(state, classStackIndex))->group_ = group;
}

void ShadowGroupElement::setShading(SoState* state, GroupShading* shading) {
  static_cast<ShadowGroupElement*>(getElement(state, classStackIndex))->shading_ = shading;
}

GroupShading* ShadowGroupElement::shading(SoState* state) {
  return static_cast<const ShadowGroupElement*>(getConstElement(state, classStackIndex))->shading_;
}

void ShadowGroupElement::setCapturing(SoState* state, bool capturing) {
  static_cast<ShadowGroupElement*>(getElement(state, classStackIndex))->capturing_ = capturing;
}

void ShadowGroupElement::setPeeling(SoState* state, bool peeling) {
  static_cast<ShadowGroupElement*>(getElement(state, classStackIndex))->peeling_ = peeling;
}

void ShadowGroupElement::setProgram(SoState* state, int variant) {
  static_cast<ShadowGroupElement*>(getElement(state, classStackIndex))->program_ = variant;
}

int ShadowGroupElement::program(SoState* state) {
  return static_cast<const ShadowGroupElement*>(getConstElement(state, classStackIndex))->program_;
}

int ShadowGroupElement::programUncached(SoState* state) {
  return static_cast<const ShadowGroupElement*>(state->getConstElement(classStackIndex))->program_;
}

GroupShading* ShadowGroupElement::activeGroup(SoState* state) {
  return static_cast<const ShadowGroupElement*>(getConstElement(state, classStackIndex))->group_;
}

bool ShadowGroupElement::capturing(SoState* state) {
  return static_cast<const ShadowGroupElement*>(getConstElement(state, classStackIndex))
      ->capturing_;
}

bool ShadowGroupElement::peeling(SoState* state) {
  return static_cast<const ShadowGroupElement*>(getConstElement(state, classStackIndex))->peeling_;
}

}  // namespace ivshadow
