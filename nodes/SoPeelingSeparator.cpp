#include "ivshadow/SoPeelingSeparator.h"

#include "ivshadow/SoTransparentShadowGroup.h"
#include "nodes/PeelingSeparatorImpl.h"

#include <Inventor/actions/SoGLRenderAction.h>

SO_NODE_SOURCE(SoPeelingSeparator);

void SoPeelingSeparator::initClass() {
  if (getClassTypeId() != SoType::badType()) return;
  // Inside a deep shadow group it shades with the group's lights; Coin may load this class
  // first (from a file that names it first), so it registers what it works with.
  SoTransparentShadowGroup::initClass();
  // Registered without the "So" prefix, as Coin registers its own nodes (see
  // SoTransparentShadowGroup).
  PRIVATE_COMMON_INIT_CODE(SoPeelingSeparator, "PeelingSeparator",
                           &SoPeelingSeparator::createInstance, SoSeparator);
}

SoPeelingSeparator::SoPeelingSeparator() : impl_(new ivshadow::PeelingSeparatorImpl(this)) {
  SO_NODE_CONSTRUCTOR(SoPeelingSeparator);
  SO_NODE_ADD_FIELD(method, (AUTO_METHOD));
  SO_NODE_ADD_FIELD(maxPasses, (0));
  SO_NODE_ADD_FIELD(earlyTermination, (TRUE));
  SO_NODE_DEFINE_ENUM_VALUE(Method, DUAL);
  SO_NODE_DEFINE_ENUM_VALUE(Method, FRONT_TO_BACK);
  SO_NODE_DEFINE_ENUM_VALUE(Method, FRAGMENT_LISTS);
  SO_NODE_DEFINE_ENUM_VALUE(Method, TRACER);
  // Files say AUTO; the C++ name is AUTO_METHOD, since SoSeparator's CacheEnabled has AUTO.
  fieldData->addEnumValue("Method", "AUTO", AUTO_METHOD);
  SO_NODE_SET_SF_ENUM_TYPE(method, Method);
}

SoPeelingSeparator::~SoPeelingSeparator() {
  delete impl_;
}

const ivshadow::PeelStatistics& SoPeelingSeparator::getStatistics() const {
  return impl_->statistics();
}

void SoPeelingSeparator::GLRenderBelowPath(SoGLRenderAction* action) {
  impl_->render(action, false);
}

void SoPeelingSeparator::GLRenderInPath(SoGLRenderAction* action) {
  impl_->render(action, true);
}

void SoPeelingSeparator::notify(SoNotList* list) {
  impl_->changed(list);
  inherited::notify(list);
}
