#include "scene/Text3Sides.h"

#include <Inventor/actions/SoCallbackAction.h>
#include <Inventor/elements/SoFontSizeElement.h>
#include <Inventor/elements/SoModelMatrixElement.h>
#include <Inventor/elements/SoProfileElement.h>
#include <Inventor/nodes/SoText3.h>

namespace ivshadow {
namespace {

SoCallbackAction::Response enter(void* data, SoCallbackAction* action, const SoNode* node) {
  auto& sides = *static_cast<Text3Sides*>(data);
  SoState* state = action->getState();
  const auto* text = static_cast<const SoText3*>(node);
  const float size = SoFontSizeElement::get(state);
  // A profiled side is scaled once (its own branch); without SIDES nothing is wrong.
  if (size == 1.0f || (text->parts.getValue() & SoText3::SIDES) == 0 ||
      SoProfileElement::get(state).getLength() > 0)
    return SoCallbackAction::CONTINUE;
  sides.begin(state, const_cast<SoNode*>(node), size);
  return SoCallbackAction::CONTINUE;
}

SoCallbackAction::Response leave(void* data, SoCallbackAction* action, const SoNode* node) {
  static_cast<Text3Sides*>(data)->end(action->getState(), const_cast<SoNode*>(node));
  return SoCallbackAction::CONTINUE;
}

}  // namespace

void Text3Sides::addTo(SoCallbackAction& action) {
  action.addPreCallback(SoText3::getClassTypeId(), enter, this);
  action.addPostCallback(SoText3::getClassTypeId(), leave, this);
}

void Text3Sides::begin(SoState* state, SoNode* node, float size) {
  active_ = true;
  size_ = size;
  model_ = SoModelMatrixElement::get(state);
  SoFontSizeElement::set(state, node, 1.0f);
  SoModelMatrixElement::scaleBy(state, node, SbVec3f(size, size, 1.0f));
}

void Text3Sides::end(SoState* state, SoNode* node) {
  if (!active_) return;
  active_ = false;
  SoModelMatrixElement::set(state, node, model_);
  SoFontSizeElement::set(state, node, size_);
}

}  // namespace ivshadow
