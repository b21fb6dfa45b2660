#pragma once

#include "ivshadow/Export.h"

#include <Inventor/elements/SoGLLazyElement.h>

namespace ivshadow {

// Keeps the material that the plugin's shading programs read (gl_FrontMaterial: ambient,
// emissive, specular, shininess) the material of the shape being drawn.
//
// Coin sends a shape's material with glMaterial just before the shape's glBegin, and Mesa
// takes such a call, made while the previous primitive's vertices are still buffered, as a
// per-vertex attribute that only its fixed-function pipeline reads (gl/CurrentMaterial.h): the
// programs kept the material of before. FreeCAD's SoBrepFaceSet draws a selected face with the
// selection colour as its emissive colour, pops the state and draws the whole shape again in
// the same node, so under the group every face of the shape came out green; two shapes with
// materials of their own, drawn one after the other, can meet it too. Coin gives no hook per
// shape, so this element takes the place of Coin's SoGLLazyElement (SoType::overrideType, as
// TexGenWatchElement): it behaves as Coin's and, whenever a node sets those parts of the
// material or a pop restores them while the plugin's programs shade the shapes, has GL draw
// what it buffered (flushBufferedVertices) and sends them at once, into an empty buffered
// format that the next primitive takes as current; the shape's own send then finds GL up to
// date. A render cache being recorded meanwhile is invalidated: its replay would send the
// material without the flush. Elsewhere, and on a GL that keeps the material
// current by itself, it only compares the material. Registered by
// ShadowGroupElement::initClass; an action's state made before keeps Coin's element until the
// action's next apply (Coin makes the state anew once elements were enabled since, as the
// plugin's are when it is loaded).
class IVSHADOW_INTERNAL MaterialSyncElement : public SoGLLazyElement {
  typedef SoGLLazyElement inherited;
  SO_ELEMENT_HEADER(MaterialSyncElement);

 public:
  static void initClass();

  void init(SoState* state) override;
  void push(SoState* state) override;
  void pop(SoState* state, const SoElement* prevTopElement) override;

 protected:
  ~MaterialSyncElement() override;
  void setAmbientElt(const SbColor* color) override;
  void setEmissiveElt(const SbColor* color) override;
  void setSpecularElt(const SbColor* color) override;
  void setShininessElt(float value) override;
  void setMaterialElt(SoNode* node, uint32_t bitmask, SoColorPacker* packer,
                      const SbColor* diffuse, const int numdiffuse, const float* transp,
                      const int numtransp, const SbColor& ambient, const SbColor& emissive,
                      const SbColor& specular, const float shininess,
                      const SbBool istransparent) override;

 private:
  // Whether `other` holds another ambient, emissive, specular colour or shininess.
  bool materialDiffers(const CoinState& other) const;
  // Sends this element's material now and has GL take it as current, where the plugin's
  // programs shade the shapes.
  void sync() const;

  SoState* state_ = nullptr;  // the setters are not given it
};

}  // namespace ivshadow
