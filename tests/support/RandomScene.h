#pragma once

#include <cstdint>
#include <string>

namespace ivshadow::test {

// An Inventor scene drawn at random from `seed` (the same seed, the same text): a camera of
// either kind, sometimes at the edge (a near plane at 1e-6, a far plane 1e9 times as far),
// shadow groups nested in groups and separators, lights of every kind inside and outside them,
// opaque and coloured transparent shapes on a floor, an instance shared under two parents,
// a SoPeelingSeparator deep inside, lines and text. For the differential test and its fuzzer.
std::string randomScene(std::uint32_t seed);

}  // namespace ivshadow::test
