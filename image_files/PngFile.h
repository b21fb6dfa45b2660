#pragma once

#include "image/Image.h"

#include <string>

namespace ivshadow {

// Writes an RGBA PNG atomically (no partial file under `path` on failure). Throws
// std::runtime_error naming the file on failure.
void writePng(const std::string& path, const Image& image);
// Writes an RGBA PNG to `file` as it is (a temporary of OutputFiles, or a device); errors
// name `name`.
void writePngTo(const std::string& file, const std::string& name, const Image& image);

// Reads any PNG libpng understands, converted to 8-bit RGBA. Throws InputError naming the file
// when it is missing or not a PNG.
Image readPng(const std::string& path);

}  // namespace ivshadow
