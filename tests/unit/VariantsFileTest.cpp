#include "scene/InputError.h"
#include "scene_input/VariantsFile.h"
#include "tests/support/TestSupport.h"

#include <gtest/gtest.h>

namespace ivshadow {
namespace {

std::vector<std::string> texts(const Variant& variant) {
  std::vector<std::string> out;
  for (const auto& assignment : variant.assignments) out.push_back(assignment.text);
  return out;
}

TEST(VariantsFile, VariantsWithAssignmentsAndComments) {
  const auto variants = parseVariants(
      "# a comment\n"
      "variant plain\n"
      "\n"
      "variant tinted   # trailing comment\n"
      "  Glass.diffuseColor = 1 0 0\n"
      "  Lamp.location=0 0 3\n",
      "v.txt");
  ASSERT_EQ(variants.size(), 2u);
  EXPECT_EQ(variants[0].name, "plain");
  EXPECT_TRUE(variants[0].assignments.empty());
  EXPECT_EQ(variants[1].name, "tinted");
  EXPECT_EQ(variants[1].line, 4);
  EXPECT_EQ(texts(variants[1]),
            (std::vector<std::string>{"Glass.diffuseColor=1 0 0", "Lamp.location=0 0 3"}));
  EXPECT_EQ(variants[1].assignments[1].line, 6);
}

TEST(VariantsFile, ANameTooLongForAnOutputFileIsRefusedWithItsLine) {
  // 200 characters name NAME.png and the rest; 201 would not leave room on every file system
  // for the temporary names.
  EXPECT_EQ(parseVariants("variant " + std::string(kMaxVariantName, 'v') + "\n", "v.variants")
                .front()
                .name.size(),
            kMaxVariantName);
  const std::string error = test::inputErrorOf([] {
    parseVariants("variant short\nvariant " + std::string(5000, 'v') + "\n", "v.variants");
  });
  EXPECT_NE(error.find("v.variants:2: error: variant name of 5000 characters; at most 200"),
            std::string::npos)
      << error;
}

// A variant named "plan" wrote its manifest over the sweep's manifests/plan.json, and a name
// of non-Latin letters was sanitised to "" and then refused as an image type: both are
// refused at their line, as is a hidden name, which the sweep's scratch files could match.
TEST(VariantsFile, NamesTheSweepNeedsOrThatKeepNothingAreRefusedWithTheirLine) {
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"variant a\nvariant plan\n",
       "v:2: error: variant name \"plan\" is taken by the sweep's own manifests/plan.json"},
      {"variant PLAN\n", "v:1: error: variant name \"PLAN\" is taken"},
      {"\nvariant .hidden\n", "v:2: error: variant name \".hidden\" begins with '.'"},
      {"sweep .s Lamp.on = TRUE\n", "v:1: error: variant name \".s-TRUE\" begins with '.'"},
      {"variant стекло\n",
       "v:1: error: variant name \"стекло\" keeps no character in a "
       "file name"},
      {"variant ***\n", "v:1: error: variant name \"***\" keeps no character"},
  };
  for (const auto& [text, expected] : cases) {
    const std::string error = test::inputErrorOf([&] { parseVariants(text, "v"); });
    EXPECT_EQ(error.rfind(expected, 0), 0u) << text << "\n" << error;
  }
  // Names that only contain such words are the variants' own.
  EXPECT_EQ(parseVariants("variant plan2\nvariant my.plan\nvariant стекло2\n", "v").size(), 3u);
}

TEST(VariantsFile, ListSweepWithSharedAssignments) {
  const auto variants = parseVariants(
      "sweep colour Glass.diffuseColor = 1 0 0 | 0 1 0\n"
      "  Lamp.resolution = 128\n",
      "v.txt");
  ASSERT_EQ(variants.size(), 2u);
  EXPECT_EQ(variants[0].name, "colour-1_0_0");
  EXPECT_EQ(texts(variants[0]),
            (std::vector<std::string>{"Glass.diffuseColor=1 0 0", "Lamp.resolution=128"}));
  EXPECT_EQ(texts(variants[1]),
            (std::vector<std::string>{"Glass.diffuseColor=0 1 0", "Lamp.resolution=128"}));
}

TEST(VariantsFile, RangeSweep) {
  const auto variants = parseVariants("sweep size Lamp.resolution = 64 .. 256 step 64\n", "v");
  ASSERT_EQ(variants.size(), 4u);
  EXPECT_EQ(variants[0].name, "size-64");
  EXPECT_EQ(texts(variants[3]), (std::vector<std::string>{"Lamp.resolution=256"}));
  const auto fractions = parseVariants("sweep a Glass.transparency = 0 .. 1 step 0.25\n", "v");
  EXPECT_EQ(fractions.size(), 5u);
  EXPECT_EQ(texts(fractions[2]), (std::vector<std::string>{"Glass.transparency=0.5"}));
}

TEST(VariantsFile, CrossedSweepMakesEveryCombinationFirstFactorSlowest) {
  const auto variants = parseVariants(
      "# header\n"
      "sweep grid Lamp.maxLayers = 1 .. 5 step 1 * Lamp.resolution = 128 | 256 | 512\n"
      "  Lamp.method = MAP\n",
      "v");
  ASSERT_EQ(variants.size(), 15u);
  // Layers 1..5 outer, resolutions inner: index = 3 * (layers - 1) + resolution index.
  const char* resolutions[] = {"128", "256", "512"};
  for (int layers = 1; layers <= 5; ++layers)
    for (int r = 0; r < 3; ++r) {
      const Variant& variant = variants[std::size_t(3 * (layers - 1) + r)];
      EXPECT_EQ(variant.name, "grid-" + std::to_string(layers) + "-" + resolutions[r]);
      EXPECT_EQ(variant.line, 2);
      EXPECT_EQ(texts(variant),
                (std::vector<std::string>{"Lamp.maxLayers=" + std::to_string(layers),
                                          std::string("Lamp.resolution=") + resolutions[r],
                                          "Lamp.method=MAP"}));
      EXPECT_EQ(variant.assignments[2].line, 3);
    }
}

TEST(VariantsFile, CrossedSweepOfThreeAndQuotedStars) {
  const auto variants =
      parseVariants("sweep s A.x = 1 | 2 * B.y = 3 | 4 * Label.string = \"a*b\" | \"c\"\n", "v");
  ASSERT_EQ(variants.size(), 8u);
  EXPECT_EQ(variants[0].name, "s-1-3-_a_b");
  EXPECT_EQ(texts(variants[7]), (std::vector<std::string>{"A.x=2", "B.y=4", "Label.string=\"c\""}));
}

// Each malformed line is reported with the file and its line.
TEST(VariantsFile, ErrorsNameTheLine) {
  const struct {
    const char* text;
    const char* expected;
  } cases[] = {
      {"Lamp.intensity = 1\n", "v:1: error: expected \"variant NAME\""},
      {"variant\n", "v:1: error: expected \"variant NAME\" with a name"},
      {"variant a\n  Lamp.intensity 1\n", "v:2: error: expected NODE.field = VALUE"},
      {"variant a\n  Lamp = 1\n", "v:2: error: expected NODE.field before '='"},
      {"variant a\n  Lamp.intensity =\n", "v:2: error: no value after '='"},
      {"variant a\nvariant a\n", "v:2: error: a second variant named \"a\""},
      {"sweep s Lamp.intensity = 1 .. 0 step 1\n", "v:1: error: the range gives 0 values"},
      {"sweep s Lamp.intensity = 0 .. 1 step -1\n", "v:1: error: expected a range"},
      // Found by VariantsFileFuzzer: the count of a range this long overflowed the integer it
      // was printed as (undefined behaviour).
      {"sweep s Lamp.maxLayers = 0 .. 2888888888888888888888888888 step 1\n",
       "v:1: error: the range gives 2.88889e+27 values; expected 1 to 10000"},
      {"sweep s Lamp.intensity = 1 || 2\n", "v:1: error: an empty value"},
      {"# nothing\n", "v:1: error: no variants"},
      {"sweep s A.x = 1 | 2 * \n", "v:1: error: expected NODE.field = VALUE"},
      {"sweep s A.x = 1 | 2 * B.y\n", "v:1: error: expected NODE.field = VALUE"},
      {"sweep s A.x = 1 .. 100 step 1 * B.y = 1 .. 101 step 1\n",
       "v:1: error: the crossed sweep gives more than 10000 variants"},
      {"sweep s A.x = 1 | 2 * B.y = 1 | 1\n", "v:1: error: a second variant named \"s-1-1\""},
  };
  for (const auto& c : cases) {
    try {
      parseVariants(c.text, "v");
      ADD_FAILURE() << "accepted: " << c.text;
    } catch (const InputError& error) {
      EXPECT_NE(std::string(error.what()).find(c.expected), std::string::npos)
          << error.what() << " for " << c.text;
    }
  }
}

TEST(VariantsFile, MissingFile) {
  EXPECT_THROW(readVariantsFile("/nonexistent/v.variants"), InputError);
}

}  // namespace
}  // namespace ivshadow
