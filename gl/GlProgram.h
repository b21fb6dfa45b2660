#pragma once

#include "ivshadow/Export.h"

#include "gl/GlHandles.h"
#include "gl/UniformLocations.h"

#include <initializer_list>
#include <string>

namespace ivshadow {

// A linked GLSL program of our own (not one Coin manages), with uniform setters by name whose
// locations were read once after linking.
class IVSHADOW_INTERNAL GlProgram {
 public:
  // Compiles and links in the current context; on failure returns an empty program and puts
  // the info log in `error`.
  static GlProgram link(const std::string& vertexSource, const std::string& fragmentSource,
                        std::string& error);

  // The same for a compute program.
  static GlProgram linkCompute(const std::string& computeSource, std::string& error);
  GlProgram() = default;
  explicit operator bool() const { return static_cast<bool>(program_); }
  unsigned int name() const { return program_.get(); }

  int location(const char* uniform) const { return uniforms_[uniform]; }
  void setInt(const char* uniform, int value) const;
  void setFloat(const char* uniform, float value) const;
  void setVec3(const char* uniform, const float* value) const;
  void setMat4(const char* uniform, const float* columnMajor) const;

 private:
  // Links the compiled `shaders` into a program and deletes them; none, with `error`, when it
  // does not link.
  static GlProgram linkShaders(std::initializer_list<unsigned int> shaders, std::string& error);
  GlProgramObject program_;
  UniformLocations uniforms_;
};

// "#version 450 compatibility", the shared constants (shaderConstantDefines()), `defines`, the
// shared declarations, then `body`: how every program of the plugin is assembled from the
// embedded .glsl files.
IVSHADOW_INTERNAL std::string composeShader(const std::string& body,
                                            const std::string& defines = {});

}  // namespace ivshadow
