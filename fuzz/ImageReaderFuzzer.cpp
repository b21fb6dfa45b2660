// libFuzzer harness: the PNG and PFM readers that `ivshadow compare` runs on the files it is
// given; the first byte picks the reader.
#include "fuzz/FuzzInput.h"
#include "image_files/PfmFile.h"
#include "image_files/PngFile.h"
#include "scene/InputError.h"

#include <stdexcept>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const bool png = data[0] & 1;
  const std::string path = ivshadow::fuzz::writeInput(data + 1, size - 1, png ? ".png" : ".pfm");
  try {
    if (png) {
      ivshadow::readPng(path);
    } else {
      int width = 0, height = 0;
      ivshadow::readPfm(path, width, height);
    }
  } catch (const std::exception&) {
    // InputError or runtime_error naming the file: a refused input.
  }
  return 0;
}
