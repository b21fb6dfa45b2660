#pragma once

#include <filesystem>
#include <string>

namespace ivshadow {

// Limits that keep Coin's recursive reader and traversals within the stack. Measured with
// `ivshadow render` on this machine (8 MiB main-thread stack): 5,000 nested separators render,
// 20,000 crash Coin's reader; a 10,000-character DEF name reads, 100,000 crash it. The
// limits leave a factor of 5 and 10 for deeper C++ stacks (an application's own callbacks,
// threads with smaller stacks); SGI's sample models nest fewer than 20 levels.
constexpr int kMaxSceneNesting = 1000;
constexpr int kMaxSceneTokenLength = 1000;

// Reads an ASCII Open Inventor or VRML file as text, following the File nodes it includes,
// before Coin reads it, and throws InputError naming the file and line of the first thing
// Coin could read but not survive: braces nested deeper than kMaxSceneNesting (counted across
// included files), a name or value longer than kMaxSceneTokenLength characters, a USE of a
// node inside that node's own DEF (a cycle: every traversal would recurse without end), a
// File that includes itself directly or through other files, and the files nodes name:
// - File and VRMLInline name scenes, checked in turn (cycles through either refused);
// - every named file that exists must be a regular file (a FIFO or /dev/zero blocked the
//   reader forever);
// - a '%' in a name Coin prints as a format is refused (File and VRMLInline naming a missing
//   file, any Texture3 name);
// - an inline image (Texture2, Image, VRMLPixelTexture image, Texture3 images) may not declare
//   more pixels than the rest of the file holds values, nor other than 0 to 4 components.
// Binary files are left to Coin.
void checkSceneFile(const std::string& path);

// Why a file of `status` is not read ("not a regular file (a FIFO); only regular files are
// read"), or an empty string for a regular file.
std::string notRegularFile(const std::filesystem::file_status& status);

}  // namespace ivshadow
