#pragma once

namespace ivshadow {

// Coin draws SoText2, SoImage and the markers of SoMarkerSet and SoIndexedMarkerSet as
// screen-aligned pixels (glBitmap, glDrawPixels), whose fragments a bound program shades
// without the vertex stage's outputs: inside a group drawn by GL its shading program coloured
// labels nearly black, and llvmpipe took seconds over them. Coin's separators call their
// children's GLRender directly, so no action method can step in: from here on, the nodes of
// these types that Coin's type system makes (every file read, SoType::createInstance, copies)
// are of a class that, where one of the plugin's programs shades the shapes, draws them with
// the program switched off in the passes that draw colours (unshadowed, as plain Coin and the
// tracer draw them) and not at all in the passes that capture positions or peel layers. Nodes
// an application makes with `new SoText2` are Coin's own. Once.
void registerScreenAlignedShapes();

}  // namespace ivshadow
