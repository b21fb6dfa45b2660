// UniformLocations: the locations GL gives, read once after linking; no look-up afterwards.
#include "gl/GlProgram.h"
#include "gl/ShadingLocations.h"
#include "gl/UniformLocations.h"
#include "nodes/ShadingProgram.h"
#include "tests/gl/GlCallCounter.h"
#include "tests/gl/GlContextTest.h"

#include <epoxy/gl.h>

#include <algorithm>
#include <string>
#include <string_view>
#include <vector>

namespace ivshadow::test {
namespace {

class UniformLocationsGLTest : public GlContextTest {
 protected:
  void SetUp() override {
    GlContextTest::SetUp();
    std::string error;
    program_ = GlProgram::link(composeShader("void main() { gl_Position = vec4(0.0); }"),
                               composeShader("uniform float uA;\n"
                                             "uniform int uB[3];\n"
                                             "uniform vec4 uUnused;\n"
                                             "out vec4 o;\n"
                                             "void main() { o = vec4(uA + float(uB[2])); }\n"),
                               error);
    ASSERT_TRUE(program_) << error;
  }
  void TearDown() override {
    // Deleted while its context is current: the fixture's TearDown destroys the context.
    program_ = GlProgram();
    GlContextTest::TearDown();
  }
  GlProgram program_;
};

TEST_F(UniformLocationsGLTest, HoldsWhatGlReports) {
  const UniformLocations locations(program_.name());
  EXPECT_EQ(locations.program(), program_.name());
  EXPECT_EQ(locations["uA"], glGetUniformLocation(program_.name(), "uA"));
  // An array by its bare name is its first element.
  EXPECT_EQ(locations["uB"], glGetUniformLocation(program_.name(), "uB[0]"));
  EXPECT_GE(locations["uB"], 0);
  // Unused (so inactive) and unknown names have none; glProgramUniform* ignores -1.
  EXPECT_EQ(locations["uUnused"], -1);
  EXPECT_EQ(locations["uMissing"], -1);
}

TEST_F(UniformLocationsGLTest, SettingByNameAsksGlNothing) {
  GlCallCounter counter;
  const UniformLocations locations(program_.name());
  const long afterLink = counter.uniformLookups();
  program_.setInt("uB", 3);
  for (int i = 0; i < 10; ++i) glProgramUniform1f(program_.name(), locations["uA"], 0.5f);
  EXPECT_EQ(counter.uniformLookups(), afterLink);
  GLfloat value = 0.0f;
  glGetUniformfv(program_.name(), locations["uA"], &value);
  EXPECT_EQ(value, 0.5f);
}

// A misspelt name in ShadingLocations' table would be -1 in every variant and its uniform
// never set: each name is declared by some shading program, and a name none declares is
// found.
TEST(ShadingLocations, EveryNameIsDeclaredByAShadingProgram) {
  const std::string text = ShadingProgram::declarations();
  EXPECT_EQ(ShadingLocations::undeclared(text), std::vector<std::string_view>{});
  EXPECT_EQ(ShadingLocations::undeclared(text + " uLightCounts").size(), 0u);
  const std::vector<std::string_view> none = ShadingLocations::undeclared("uLightCounts");
  EXPECT_NE(std::find(none.begin(), none.end(), "uLightCount"), none.end());
}

TEST_F(UniformLocationsGLTest, ShadingLocationsAreTheProgramsLocations) {
  const ShadingLocations locations{UniformLocations(program_.name())};
  EXPECT_EQ(locations.program, program_.name());
  EXPECT_EQ(locations.uLightCount, -1);
  EXPECT_EQ(locations.uMapRay, -1);
}

}  // namespace
}  // namespace ivshadow::test
