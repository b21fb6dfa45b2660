#pragma once

#include "image/Image.h"

#include <string>

namespace ivshadow {

// Writes the RGB of an RGBA image as a baseline JPEG (libjpeg, `quality` 1..100) atomically:
// no partial file under `path` on failure. Throws std::runtime_error naming the file.
void writeJpeg(const std::string& path, const Image& image, int quality = 92);
// Writes the JPEG to `file` as it is (a temporary of OutputFiles, or a device); errors name
// `name`.
void writeJpegTo(const std::string& file, const std::string& name, const Image& image,
                 int quality = 92);

// Reads a JPEG as 8-bit RGBA (alpha 255). Throws InputError naming the file when it is
// missing or not a JPEG libjpeg can decode.
Image readJpeg(const std::string& path);

}  // namespace ivshadow
