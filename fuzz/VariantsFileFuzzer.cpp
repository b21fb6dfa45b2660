// libFuzzer harness: variants files as `ivshadow variants` reads them.
#include "fuzz/FuzzInput.h"
#include "scene/InputError.h"
#include "scene_input/VariantsFile.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    ivshadow::parseVariants(text, "fuzz.variants");
  } catch (const ivshadow::InputError&) {
  }
  return 0;
}
