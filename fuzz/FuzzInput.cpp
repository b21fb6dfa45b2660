#include "fuzz/FuzzInput.h"

#include "headless/CoinOffscreenContexts.h"
#include "ivshadow/IvShadowInit.h"

#include <Inventor/errors/SoDebugError.h>
#include <Inventor/errors/SoReadError.h>

#include <unistd.h>

#include <fstream>
#include <mutex>

namespace ivshadow::fuzz {
namespace {

void quiet(const SoError*, void*) {}

}  // namespace

std::string writeInput(const std::uint8_t* data, std::size_t size, const char* suffix) {
  const std::string path = "/dev/shm/ivshadow-fuzz-" + std::to_string(::getpid()) + suffix;
  std::ofstream(path, std::ios::binary | std::ios::trunc)
      .write(reinterpret_cast<const char*>(data), std::streamsize(size));
  return path;
}

void initOnce() {
  static std::once_flag once;
  std::call_once(once, [] {
    init();
    // NURBS shapes in the input are tessellated through an offscreen context (headless).
    installCoinOffscreenContexts();
    SoDebugError::setHandlerCallback(quiet, nullptr);
    SoReadError::setHandlerCallback(quiet, nullptr);
  });
}

}  // namespace ivshadow::fuzz
