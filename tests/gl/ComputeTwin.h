#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace ivshadow::test {

// Runs a compute program over a buffer of cases in the current GL context, for the tests that
// hold a GLSL function to its C++ twin. `body` follows the plugin's shared texts
// (composeShader) and reads uCount cases from the std430 buffer at binding 0 and writes one
// result per case to binding 1, 64 invocations a group. Returns false, with `error`, when the
// program does not link.
bool runComputeCases(const char* body, const void* cases, std::size_t count, std::size_t caseSize,
                     void* results, std::size_t resultSize, std::string& error);

// The same for typed cases and results, laid out as the program's std430 structs; empty when
// the program does not link.
template <class Result, class Case>
std::vector<Result> computeCases(const char* body, const std::vector<Case>& cases,
                                 std::string& error) {
  std::vector<Result> results(cases.size());
  if (!runComputeCases(body, cases.data(), cases.size(), sizeof(Case), results.data(),
                       sizeof(Result), error))
    return {};
  return results;
}

}  // namespace ivshadow::test
