#pragma once

#include <cstddef>
#include <cstdint>
#include <string>

namespace ivshadow::fuzz {

// The readers under test take file paths (as the command line hands them over): the input
// is written to one file per process in /dev/shm (memory, no disk) and its path returned.
std::string writeInput(const std::uint8_t* data, std::size_t size, const char* suffix);

// Coin and the plugin's nodes, registered once; Coin's messages silenced so the fuzzer's
// output stays readable (errors are still returned to the code under test).
void initOnce();

}  // namespace ivshadow::fuzz
