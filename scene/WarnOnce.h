#pragma once

#include "ivshadow/Export.h"

#include <string>

namespace ivshadow {

// Whether this is the first time the process is about to warn about `what` of `subject` (a
// node, or null for what concerns the process as a whole): the warnings of the plugin and of
// the casters' extraction are said once, not on every frame or by every renderer. The keys
// are the process's and guarded by one mutex, so that contexts rendering at once on several
// threads neither race on the set nor say a warning twice. A node freed and another made at
// its address is taken for the same node (one warning fewer, never one more) unless the
// first one said it was going (forgetWarnings).
bool firstWarning(const void* subject, const std::string& what = std::string());

// Forgets what was said of `subject`: the plugin's nodes call it as they are destroyed, so
// that a node made later at the same address is warned about in its own right.
void forgetWarnings(const void* subject);

// Forgets every warning said: a process that renders one scene after another (a variants
// worker) says each scene's warnings as a process of its own would, those of the process as a
// whole and of Coin's own nodes (which do not call forgetWarnings) included.
IVSHADOW_INTERNAL void forgetAllWarnings();

}  // namespace ivshadow
