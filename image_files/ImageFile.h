#pragma once

#include "image/Image.h"

#include <string>

namespace ivshadow {

enum class ImageFormat { Png, Jpeg };

// The extensions imageFormatFor knows, as messages list them: ".png, .jpg, .jpeg".
inline constexpr const char* kImageExtensions = ".png, .jpg, .jpeg";

// The format `path`'s extension names, case-insensitively: .png, .jpg or .jpeg; PNG for an
// existing device or pipe of another name (`/dev/null`), which is written in place. Throws
// InputError naming `path` and the supported extensions for any other (or none), so a
// command refuses an output name before doing any work instead of writing PNG data under a
// .jpg name.
ImageFormat imageFormatFor(const std::string& path);

// Writes `image` atomically in the format its file name asks for (imageFormatFor). JPEG has
// no alpha channel: the colour is written as rendered, alpha dropped.
void writeImage(const std::string& path, const Image& image);
// Writes `image` to `file` as it is (a temporary of OutputFiles, or a device) in the format
// `name` asks for; errors name `name`.
void writeImageTo(const std::string& file, const std::string& name, const Image& image);

// Reads a PNG or JPEG as 8-bit RGBA, chosen by the file name like writeImage. Throws
// InputError naming the file when it is of another type, missing or unreadable.
Image readImage(const std::string& path);

}  // namespace ivshadow
