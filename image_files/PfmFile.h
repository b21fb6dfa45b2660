#pragma once

#include <string>
#include <vector>

namespace ivshadow {

// Writes floating-point RGB (rows top to bottom, 3 floats a pixel) as a Portable Float Map:
// the unrounded values, for comparisons finer than 8 bits. Atomic like writePng.
void writePfm(const std::string& path, int width, int height, const std::vector<float>& rgb);
// Writes the PFM to `file` as it is (a temporary of OutputFiles, or a device); errors name
// `name`.
void writePfmTo(const std::string& file, const std::string& name, int width, int height,
                const std::vector<float>& rgb);

// Reads a colour PFM ("PF") back, rows top to bottom. Throws InputError naming the file.
std::vector<float> readPfm(const std::string& path, int& width, int& height);

}  // namespace ivshadow
