#include "image_files/PfmFile.h"

#include "image_files/AtomicFile.h"
#include "scene/InputError.h"

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <stdexcept>

namespace ivshadow {
namespace {

bool littleEndianHost() {
  const std::uint16_t one = 1;
  unsigned char first = 0;
  std::memcpy(&first, &one, 1);
  return first == 1;
}

}  // namespace

void writePfm(const std::string& path, int width, int height, const std::vector<float>& rgb) {
  AtomicFile file(path);
  writePfmTo(file.temporaryPath(), path, width, height, rgb);
  file.commit();
}

void writePfmTo(const std::string& file, const std::string& path, int width, int height,
                const std::vector<float>& rgb) {
  std::ofstream out(file, std::ios::binary);
  // A negative scale says little-endian; PFM stores rows bottom to top.
  out << "PF\n" << width << ' ' << height << '\n' << (littleEndianHost() ? "-1.0" : "1.0") << '\n';
  for (int y = height - 1; y >= 0; --y)
    out.write(reinterpret_cast<const char*>(&rgb[std::size_t(y) * std::size_t(width) * 3]),
              std::streamsize(std::size_t(width) * 3 * sizeof(float)));
  out.close();
  if (!out) throw std::runtime_error(path + ": error: cannot write the float image");
}

std::vector<float> readPfm(const std::string& path, int& width, int& height) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path + ": error: cannot open the float image");
  std::string magic;
  float scale = 0.0f;
  in >> magic >> width >> height >> scale;
  in.get();
  if (magic != "PF" || width <= 0 || height <= 0 || !in)
    throw InputError(path + ":1: error: expected a colour PFM header 'PF', width, height, scale");
  if ((scale < 0.0f) != littleEndianHost())
    throw InputError(path + ":3: error: byte order of this PFM differs from the machine's");
  // The header's size is checked against the data the file holds before anything is
  // allocated: a header alone may ask for gigabytes (found by ImageReaderFuzzer: "8 118888888"
  // asked for 11 GB).
  const std::streamoff start = in.tellg();
  in.seekg(0, std::ios::end);
  const std::streamoff available = in.tellg() - start;
  in.seekg(start);
  // Compared as pixels, not bytes: width x height x 12 can pass 2^64 and wrap.
  constexpr std::uint64_t kPixelBytes = 3 * sizeof(float);
  const std::uint64_t pixels = std::uint64_t(width) * std::uint64_t(height);
  if (start < 0 || available < 0 || std::uint64_t(available) / kPixelBytes < pixels)
    throw InputError(path + ": error: the header asks for " + std::to_string(width) + " x " +
                     std::to_string(height) + " pixels of " + std::to_string(kPixelBytes) +
                     " bytes; the file holds " +
                     std::to_string(std::max<std::streamoff>(available, 0)) + " bytes of pixels");
  std::vector<float> rgb(std::size_t(width) * std::size_t(height) * 3);
  for (int y = height - 1; y >= 0; --y)
    in.read(reinterpret_cast<char*>(&rgb[std::size_t(y) * std::size_t(width) * 3]),
            std::streamsize(std::size_t(width) * 3 * sizeof(float)));
  if (!in) throw InputError(path + ": error: the float image ends early");
  return rgb;
}

}  // namespace ivshadow
