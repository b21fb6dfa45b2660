#include "nodes/LightScopeElement.h"

#include "gl/ShadingUniforms.h"

#include <Inventor/SoType.h>
#include <Inventor/elements/SoGLLightIdElement.h>

namespace ivshadow {
namespace {

// Coin's element (its type, stack index and behaviour) with the lights it turns off darkened.
class LightScopeElement : public SoGLLightIdElement {
 public:
  static void* create() { return new LightScopeElement; }

  void pop(SoState* state, const SoElement* prevTopElement) override {
    SoGLLightIdElement::pop(state, prevTopElement);
    // The same lights SoGLLightIdElement::pop turned off: this level's count up to the one
    // the ended level had reached.
    const int ended = static_cast<const LightScopeElement*>(prevTopElement)->data;
    if (ended > data) darkenLights(int(data) + 1, int(ended) + 1);
  }

 protected:
  ~LightScopeElement() override = default;
};

}  // namespace

void registerLightScopeElement() {
  static const bool registered = [] {
    SoType::overrideType(SoGLLightIdElement::getClassTypeId(), LightScopeElement::create);
    return true;
  }();
  (void)registered;
}

}  // namespace ivshadow
