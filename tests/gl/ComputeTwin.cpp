#include "tests/gl/ComputeTwin.h"

#include "gl/GlHandles.h"
#include "gl/GlProgram.h"

#include <epoxy/gl.h>

#include <string>

namespace ivshadow::test {
namespace {

// What every twin program shares: its buffers and a main() that evaluates each case.
constexpr const char* kMain = R"glsl(
layout(local_size_x = 64) in;
layout(std430, binding = 0) readonly buffer Cases { Case cases[]; };
layout(std430, binding = 1) writeonly buffer Results { Result results[]; };
uniform int uCount;
void main() {
  int i = int(gl_GlobalInvocationID.x);
  if (i < uCount) results[i] = evaluate(cases[i]);
}
)glsl";

}  // namespace

bool runComputeCases(const char* body, const void* cases, std::size_t count, std::size_t caseSize,
                     void* results, std::size_t resultSize, std::string& error) {
  const GlProgram program = GlProgram::linkCompute(composeShader(std::string(body) + kMain), error);
  if (!program) return false;
  const GlBuffer input = createBuffer(), output = createBuffer();
  glNamedBufferData(input.get(), GLsizeiptr(count * caseSize), cases, GL_STATIC_DRAW);
  glNamedBufferData(output.get(), GLsizeiptr(count * resultSize), nullptr, GL_STATIC_READ);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, input.get());
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, output.get());
  glUseProgram(program.name());
  program.setInt("uCount", int(count));
  glDispatchCompute(GLuint((count + 63) / 64), 1, 1);
  glMemoryBarrier(GL_BUFFER_UPDATE_BARRIER_BIT);
  glGetNamedBufferSubData(output.get(), 0, GLsizeiptr(count * resultSize), results);
  glUseProgram(0);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 0, 0);
  glBindBufferBase(GL_SHADER_STORAGE_BUFFER, 1, 0);
  return true;
}

}  // namespace ivshadow::test
