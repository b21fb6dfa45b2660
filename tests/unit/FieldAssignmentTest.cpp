#include "ivshadow/IvShadowInit.h"
#include "scene/InputError.h"
#include "scene_input/FieldAssignment.h"

#include <Inventor/SoDB.h>
#include <Inventor/SoInput.h>
#include <Inventor/nodes/SoMaterial.h>
#include <Inventor/nodes/SoSeparator.h>

#include <gtest/gtest.h>

#include <cstring>

namespace ivshadow {
namespace {

class FieldAssignmentTest : public ::testing::Test {
 protected:
  void SetUp() override {
    init();
    static const char* scene =
        "#Inventor V2.1 ascii\n"
        "Separator { DEF Glass Material { diffuseColor 1 1 1 transparency 0.5 }"
        " Switch { whichChild -1 DEF Hidden Material {} } Cube {} }";
    SoInput input;
    input.setBuffer(scene, std::strlen(scene));
    root_ = SoDB::readAll(&input);
    ASSERT_NE(root_, nullptr);
    root_->ref();
  }
  void TearDown() override {
    if (root_) root_->unref();
  }
  SoMaterial* named(const char* name) { return static_cast<SoMaterial*>(SoNode::getByName(name)); }

  std::string errorOf(const std::string& text) {
    try {
      FieldAssignment::parse(text).apply(root_, "scene.iv");
    } catch (const InputError& error) {
      return error.what();
    }
    return {};
  }

  SoSeparator* root_ = nullptr;
};

TEST_F(FieldAssignmentTest, SplitsNameFieldAndValue) {
  const FieldAssignment a = FieldAssignment::parse("Glass.diffuseColor=1 0 0");
  EXPECT_EQ(a.node, "Glass");
  EXPECT_EQ(a.field, "diffuseColor");
  EXPECT_EQ(a.value, "1 0 0");
  EXPECT_EQ(FieldAssignment::parse("A.b=x=y").value, "x=y");
}

TEST_F(FieldAssignmentTest, SetsFieldsWithCoinsParser) {
  FieldAssignment::parse("Glass.diffuseColor=1 0 0.25").apply(root_, "scene.iv");
  FieldAssignment::parse("Glass.transparency=0.125").apply(root_, "scene.iv");
  EXPECT_EQ(named("Glass")->diffuseColor[0], SbColor(1.0f, 0.0f, 0.25f));
  EXPECT_FLOAT_EQ(named("Glass")->transparency[0], 0.125f);
}

TEST_F(FieldAssignmentTest, ReachesNodesUnderSwitchedOffSwitches) {
  FieldAssignment::parse("Hidden.shininess=0.75").apply(root_, "scene.iv");
  EXPECT_FLOAT_EQ(named("Hidden")->shininess[0], 0.75f);
}

TEST_F(FieldAssignmentTest, RejectsTextWithoutNameFieldAndValue) {
  for (const char* bad : {"Glass", "Glass=1", ".field=1", "Glass.=1", "Glassfield=1"}) {
    EXPECT_THROW(FieldAssignment::parse(bad), InputError) << bad;
  }
}

TEST_F(FieldAssignmentTest, UnknownNodeListsTheNamesThatExist) {
  const std::string error = errorOf("Glas.transparency=0.5");
  EXPECT_NE(error.find("no node named 'Glas' in scene.iv"), std::string::npos) << error;
  EXPECT_NE(error.find("Glass"), std::string::npos) << error;
}

TEST_F(FieldAssignmentTest, UnknownFieldListsTheNodesFields) {
  const std::string error = errorOf("Glass.colour=1 0 0");
  EXPECT_NE(error.find("has no field 'colour'"), std::string::npos) << error;
  EXPECT_NE(error.find("diffuseColor"), std::string::npos) << error;
}

TEST_F(FieldAssignmentTest, UnparsableValueNamesTheFieldTypeAndLeavesTheFieldAlone) {
  const std::string error = errorOf("Glass.transparency=opaque");
  EXPECT_NE(error.find("cannot parse 'opaque' as MFFloat for Glass.transparency"),
            std::string::npos)
      << error;
  EXPECT_FLOAT_EQ(named("Glass")->transparency[0], 0.5f);
}

// SoField::set alone stops where the value's syntax ends and drops the rest; the same text in
// a file fails to read, so --set and variants files must fail as well.
TEST_F(FieldAssignmentTest, TextLeftAfterTheValueIsAnErrorAndLeavesTheFieldAlone) {
  EXPECT_NE(errorOf("Glass.diffuseColor=0 0 1 garbage")
                .find("cannot parse '0 0 1 garbage' as MFColor for Glass.diffuseColor ('garbage' "
                      "follows the value)"),
            std::string::npos)
      << errorOf("Glass.diffuseColor=0 0 1 garbage");
  EXPECT_EQ(named("Glass")->diffuseColor[0], SbColor(1, 1, 1));
  EXPECT_NE(errorOf("Glass.transparency=0.25x").find("('x' follows the value)"), std::string::npos)
      << errorOf("Glass.transparency=0.25x");
  EXPECT_FLOAT_EQ(named("Glass")->transparency[0], 0.5f);
  // Whole values in every form Coin reads still pass: lists, a trailing space.
  EXPECT_EQ(errorOf("Glass.diffuseColor=[1 0 0, 0 1 0] "), "");
  EXPECT_EQ(named("Glass")->diffuseColor.getNum(), 2);
}

// Issue 35: Coin reads a float it cannot hold as 0 after a read error and goes on; --set
// "1e39 0 0" silently put a light at the origin where the same value in a file is refused.
TEST_F(FieldAssignmentTest, NumbersCoinCannotHoldAreAnErrorAndLeaveTheFieldAlone) {
  const std::string error = errorOf("Glass.transparency=1e39");
  EXPECT_NE(error.find("cannot parse '1e39' as MFFloat for Glass.transparency (Detected "
                       "non-valid floating point number"),
            std::string::npos)
      << error;
  EXPECT_FLOAT_EQ(named("Glass")->transparency[0], 0.5f);
  EXPECT_NE(errorOf("Glass.diffuseColor=1e39 0 0").find("cannot parse"), std::string::npos);
  EXPECT_EQ(named("Glass")->diffuseColor[0], SbColor(1, 1, 1));
  // The largest float still reads.
  EXPECT_EQ(errorOf("Glass.transparency=3e38"), "");
}

}  // namespace
}  // namespace ivshadow
