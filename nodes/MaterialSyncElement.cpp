#include "nodes/MaterialSyncElement.h"

#include "gl/CurrentMaterial.h"
#include "nodes/ShadowGroupElement.h"

#include <Inventor/elements/SoCacheElement.h>
#include <Inventor/misc/SoState.h>

namespace ivshadow {

SO_ELEMENT_SOURCE(MaterialSyncElement);

void MaterialSyncElement::initClass() {
  if (getClassTypeId() != SoType::badType()) return;
  SO_ELEMENT_INIT_CLASS(MaterialSyncElement, inherited);
  SoType::overrideType(SoGLLazyElement::getClassTypeId(), &MaterialSyncElement::createInstance);
}

MaterialSyncElement::~MaterialSyncElement() = default;

void MaterialSyncElement::init(SoState* state) {
  inherited::init(state);
  state_ = state;
}

void MaterialSyncElement::push(SoState* state) {
  inherited::push(state);
  state_ = state;
}

void MaterialSyncElement::pop(SoState* state, const SoElement* prevTopElement) {
  inherited::pop(state, prevTopElement);
  // The element popped may be Coin's own, in a state made before this one was registered:
  // its material is not known here, so it is taken to differ.
  const bool known = prevTopElement->getTypeId().isDerivedFrom(getClassTypeId());
  if (!known ||
      materialDiffers(static_cast<const MaterialSyncElement*>(prevTopElement)->coinstate))
    sync();
}

void MaterialSyncElement::setAmbientElt(const SbColor* color) {
  inherited::setAmbientElt(color);
  sync();
}

void MaterialSyncElement::setEmissiveElt(const SbColor* color) {
  inherited::setEmissiveElt(color);
  sync();
}

void MaterialSyncElement::setSpecularElt(const SbColor* color) {
  inherited::setSpecularElt(color);
  sync();
}

void MaterialSyncElement::setShininessElt(float value) {
  inherited::setShininessElt(value);
  sync();
}

void MaterialSyncElement::setMaterialElt(SoNode* node, uint32_t bitmask, SoColorPacker* packer,
                                         const SbColor* diffuse, const int numdiffuse,
                                         const float* transp, const int numtransp,
                                         const SbColor& ambient, const SbColor& emissive,
                                         const SbColor& specular, const float shininess,
                                         const SbBool istransparent) {
  const CoinState before = coinstate;
  inherited::setMaterialElt(node, bitmask, packer, diffuse, numdiffuse, transp, numtransp,
                            ambient, emissive, specular, shininess, istransparent);
  if (materialDiffers(before)) sync();
}

bool MaterialSyncElement::materialDiffers(const CoinState& other) const {
  return other.ambient != coinstate.ambient || other.emissive != coinstate.emissive ||
         other.specular != coinstate.specular || other.shininess != coinstate.shininess;
}

void MaterialSyncElement::sync() const {
  // Actions that draw with GL but never enabled the plugin's element draw no shape with its
  // programs. The program is read without recording the plugin's element in a render cache
  // being built: this also runs while the state pops, and recording it there made FreeCAD's
  // saveImage draw nothing of the scene (freecad.addon_editing, its point light's picture).
  if (state_ == nullptr ||
      !state_->isElementEnabled(ShadowGroupElement::getClassStackIndex()) ||
      ShadowGroupElement::programUncached(state_) < 0 || !materialLagsBehindGlMaterial())
    return;
  // A render cache's replay would send the material without the flush: none records it.
  if (state_->isCacheOpen()) SoCacheElement::invalidate(state_);
  // What is buffered is drawn with the material it was given, then the new material is sent
  // into an empty format, which the next glBegin takes as current.
  flushBufferedVertices();
  send(state_, AMBIENT_MASK | SPECULAR_MASK | EMISSIVE_MASK | SHININESS_MASK);
}

}  // namespace ivshadow
