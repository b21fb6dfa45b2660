#pragma once

namespace ivshadow {

// Gives Coin its offscreen GL contexts through EGL. Coin makes one when a non-GL action (the
// casters' SoCallbackAction, the reference's extraction) asks an SoNurbsSurface or
// SoNurbsCurve for triangles: SGI's GLU tessellator calls GL even when it only tessellates.
// Coin's own implementation opens an X display with GLX and, with no display, dereferences
// the null it got (a segmentation fault in XDefaultScreenOfDisplay) - which is every headless
// run here. Installed once per process (cc_glglue_context_set_offscreen_cb_functions); safe to
// call again. Each context is a surfaceless EGL context; making it current remembers the
// thread's current context and reinstating puts that one back: an EGL context, or the GLX
// context of a window (the viewer's), for which Coin's own GLX offscreen contexts fail under
// Mesa's software GLX ("Couldn't create GLX context"), so NURBS shapes cast no shadow there.
void installCoinOffscreenContexts();

}  // namespace ivshadow
