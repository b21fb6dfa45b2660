#pragma once

namespace ivshadow {

// Mesa (every driver of it, llvmpipe included) buffers the vertices of glBegin/glEnd
// primitives. A glMaterial call that comes while the buffered format still has a position (the
// vertices of a primitive before are buffered, and GL changed no state since) becomes a
// per-vertex attribute of the primitives that follow: Mesa's fixed-function pipeline reads it,
// but a GLSL program's gl_FrontMaterial keeps the material of before until GL next takes the
// buffered attributes into its current state. A query of the material does that at once, so
// it may not come between the call and the draw of the vertices buffered before it: those
// would then be drawn with the new material.

// Whether the GL of the current context is one that does so (Mesa names itself in
// GL_VERSION, "4.5 (Compatibility Profile) Mesa 22.3.6", whichever driver draws). Other GL
// implementations keep the material current by themselves.
bool materialLagsBehindGlMaterial();

// Draws the buffered vertices with the material they were given and empties the buffered
// format (glFlush: Mesa flushes its buffered vertices before anything else it does), so that
// the glMaterial calls that follow are taken as the current material by the next primitive
// (Mesa's glBegin takes attributes given outside a primitive as current when the buffered
// format has no position). Only where materialLagsBehindGlMaterial(): elsewhere it is not
// needed.
void flushBufferedVertices();

}  // namespace ivshadow
