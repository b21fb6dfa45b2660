#pragma once

#include "ivshadow/Export.h"

#include <string>

namespace ivshadow {

// The kinds of GL object the passes allocate and check: a fragment list's storage is a
// buffer, told apart so that tests can fail it alone (the lists then peel instead).
// FragmentSlots: the camera's fragment lists with slots of their own in each pixel (a failure
// there makes them try fewer, down to none, before they are counted as FragmentList's).
enum class GlAllocation { Texture, Buffer, Framebuffer, FragmentList, FragmentSlots };

// A glGetError code by its name ("GL_OUT_OF_MEMORY"; "GL error 0x..." for one GL does not
// list): the passes' messages and the GL tests' reports name errors alike.
IVSHADOW_INTERNAL std::string glErrorName(unsigned int error);

// Takes GL's pending errors off: an error raised before an allocation is not the
// allocation's, and would otherwise be taken for its failure.
void clearGlErrors();

// After allocating objects of `kind` since clearGlErrors(): empty when GL raised no error;
// else the error by name ("GL_OUT_OF_MEMORY"). Takes GL's errors off.
// IVSHADOW_FAIL_GL, a comma-separated list of texture, buffer, framebuffer, list and slots read
// once per process, makes the kinds it names fail here as if GL had run out of memory: the one
// place tests force the failures the passes must survive (docs/RELIABILITY.md).
std::string glAllocationError(GlAllocation kind);

// Empty when framebuffer object `framebuffer` is complete (glCheckNamedFramebufferStatus);
// else its status by name. IVSHADOW_FAIL_GL=framebuffer reports every one incomplete.
std::string framebufferIncompleteness(unsigned int framebuffer);

}  // namespace ivshadow
