#include "gl/GlProgram.h"

#include "GlslSources.h"
#include "gl/ShaderConstants.h"

#include <epoxy/gl.h>

#include <vector>

namespace ivshadow {
namespace {

std::string infoLog(GLuint object, bool program) {
  GLint length = 0;
  if (program)
    glGetProgramiv(object, GL_INFO_LOG_LENGTH, &length);
  else
    glGetShaderiv(object, GL_INFO_LOG_LENGTH, &length);
  std::vector<char> text(static_cast<std::size_t>(length > 0 ? length : 1), '\0');
  if (program)
    glGetProgramInfoLog(object, length, nullptr, text.data());
  else
    glGetShaderInfoLog(object, length, nullptr, text.data());
  return std::string(text.data());
}

GLuint compile(GLenum stage, const std::string& source, std::string& error) {
  const GLuint shader = glCreateShader(stage);
  const char* text = source.c_str();
  glShaderSource(shader, 1, &text, nullptr);
  glCompileShader(shader);
  GLint ok = GL_FALSE;
  glGetShaderiv(shader, GL_COMPILE_STATUS, &ok);
  if (!ok) {
    error = std::string(stage == GL_VERTEX_SHADER    ? "vertex"
                        : stage == GL_COMPUTE_SHADER ? "compute"
                                                     : "fragment") +
            " shader does not compile: " + infoLog(shader, false);
    glDeleteShader(shader);
    return 0;
  }
  return shader;
}

}  // namespace

std::string composeShader(const std::string& body, const std::string& defines) {
  return "#version 450 compatibility\n" + shaderConstantDefines() + defines +
         glsl::kDeepShadowCommonGlsl + glsl::kSurfaceOpticsGlsl + glsl::kLightEquationGlsl + body;
}

GlProgram GlProgram::link(const std::string& vertexSource, const std::string& fragmentSource,
                          std::string& error) {
  const GLuint vertex = compile(GL_VERTEX_SHADER, vertexSource, error);
  if (vertex == 0) return {};
  const GLuint fragment = compile(GL_FRAGMENT_SHADER, fragmentSource, error);
  if (fragment == 0) {
    glDeleteShader(vertex);
    return {};
  }
  return linkShaders({vertex, fragment}, error);
}

GlProgram GlProgram::linkCompute(const std::string& computeSource, std::string& error) {
  const GLuint compute = compile(GL_COMPUTE_SHADER, computeSource, error);
  if (compute == 0) return {};
  return linkShaders({compute}, error);
}

GlProgram GlProgram::linkShaders(std::initializer_list<unsigned int> shaders, std::string& error) {
  GlProgram result;
  result.program_ = GlProgramObject(glCreateProgram());
  const GLuint program = result.program_.get();
  for (const GLuint shader : shaders) glAttachShader(program, shader);
  glLinkProgram(program);
  // Attached, the shaders live as long as the program needs them.
  for (const GLuint shader : shaders) glDeleteShader(shader);
  GLint ok = GL_FALSE;
  glGetProgramiv(program, GL_LINK_STATUS, &ok);
  if (!ok) {
    error = "program does not link: " + infoLog(program, true);
    return {};
  }
  result.uniforms_ = UniformLocations(program);
  return result;
}

void GlProgram::setInt(const char* uniform, int value) const {
  glProgramUniform1i(program_.get(), location(uniform), value);
}
void GlProgram::setFloat(const char* uniform, float value) const {
  glProgramUniform1f(program_.get(), location(uniform), value);
}
void GlProgram::setVec3(const char* uniform, const float* value) const {
  glProgramUniform3fv(program_.get(), location(uniform), 1, value);
}
void GlProgram::setMat4(const char* uniform, const float* columnMajor) const {
  glProgramUniformMatrix4fv(program_.get(), location(uniform), 1, GL_FALSE, columnMajor);
}

}  // namespace ivshadow
