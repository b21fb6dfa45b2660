#include "image_files/MemoryBudget.h"
#include "tests/support/TestSupport.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <map>
#include <sstream>

namespace ivshadow {
namespace {

using test::run;

std::vector<std::string> csvFields(const std::string& line) {
  std::vector<std::string> fields;
  std::string field;
  bool quoted = false;
  for (char c : line) {
    if (c == '"') {
      quoted = !quoted;
    } else if (c == ',' && !quoted) {
      fields.push_back(field);
      field.clear();
    } else {
      field += c;
    }
  }
  fields.push_back(field);
  return fields;
}

TEST(TradeCommand, EverySettingIsTimedAndMeasuredAgainstTheReference) {
  const std::string dir = test::outputDir();
  const test::ProcessResult result =
      run({test::ivshadowExe(), "trade", test::scenesDir() + "/coloured_shadows.iv", "-o", dir,
           "--size", "160x120", "--resolution", "32,512", "--layers", "1,4", "--slices", "1,16",
           "--precision", "float", "--filter", "none", "--frames", "2"});
  ASSERT_EQ(result.exitCode, 0) << result.err;
  // The count said is the count the progress ran to: each row, the baselines with the
  // settings (it once said "11 settings" after counting to 13).
  EXPECT_NE(result.err.find("[13/13] "), std::string::npos) << result.err;
  EXPECT_NE(result.out.find("trade.svg: 13 rows, 11 shadow settings and 2 baselines"),
            std::string::npos)
      << result.out;
  std::ifstream in(dir + "/trade.csv");
  std::string line;
  std::getline(in, line);
  const std::vector<std::string> header = csvFields(line);
  ASSERT_EQ(header[0], "setting");
  std::map<std::string, std::vector<std::string>> rows;
  while (std::getline(in, line)) {
    const std::vector<std::string> fields = csvFields(line);
    ASSERT_EQ(fields.size(), header.size()) << line;
    rows[fields[0]] = fields;
  }
  // Two baselines, 2 x 2 map settings, the traced one, the group traced whole, the shadow
  // volumes and 2 x 2 opacity maps.
  ASSERT_EQ(rows.size(), 13u);
  const auto value = [&](const std::string& row, const std::string& column) {
    const auto at = std::find(header.begin(), header.end(), column) - header.begin();
    return std::stod(rows.at(row).at(std::size_t(at)));
  };
  EXPECT_EQ(value("exact (CPU reference)", "rmse"), 0.0);
  // A finer map with more layers is closer to the exact answer than a 32-texel single
  // layer, and any shadows are closer than none.
  EXPECT_LT(value("512 4L float", "rmse"), value("32 1L float", "rmse"));
  EXPECT_LT(value("32 1L float", "rmse"), value("no shadows (plain Coin)", "rmse"));
  // Exact shadows: no map setting comes closer (what is left is the camera view's error).
  EXPECT_LE(value("rays (exact)", "rmse"), value("512 4L float", "rmse"));
  EXPECT_GT(value("rays (exact)", "map_bytes"), 0.0);  // the BVH
  // The group traced whole is the reference's picture drawn through GL: what is left is the
  // rounding to 8 bits after the blend (under half a step on average).
  EXPECT_LT(value("group traced (TRACER)", "rmse"), 0.5);
  EXPECT_GT(value("group traced (TRACER)", "rebuild_frame_ms"), 0.0);
  // The volumes are exact too, but for the scene's textured checkerboard, whose volume casts
  // its mean colour: still closer than the coarse map, and they keep no map.
  EXPECT_LT(value("shadow volumes (exact, hard)", "rmse"), value("32 1L float", "rmse"));
  EXPECT_EQ(value("shadow volumes (exact, hard)", "map_bytes"), 0.0);
  EXPECT_GT(value("512 4L float", "build_ms"), 0.0);
  EXPECT_GT(value("512 4L float", "map_bytes"), value("32 1L float", "map_bytes"));
  // The opacity maps: more slices come closer (the slices span the transparent casters only,
  // so the floor beyond them is exact at any count; what lies among them, the glass sphere's
  // far side and a pane behind another, is within the one slice of 1 and mostly a slice or
  // more behind at 16), and keep 4 + 16 bytes per slice per texel on six faces.
  EXPECT_LT(value("opacity 512 16S float", "rmse"), value("opacity 512 1S float", "rmse"));
  EXPECT_LT(value("opacity 512 1S float", "rmse"), value("no shadows (plain Coin)", "rmse"));
  EXPECT_EQ(value("opacity 512 16S float", "map_bytes"), 512.0 * 512.0 * 6.0 * (4 + 16 * 16));
  EXPECT_EQ(value("opacity 32 1S float", "layers"), 1.0);
  // The chart names each row on the front and the baselines (tests/gl/TradePlotTest.cpp
  // checks its geometry).
  const std::string chart = test::readText(dir + "/trade.svg");
  EXPECT_NE(chart.find(">no shadows (plain Coin)</text>"), std::string::npos);
  EXPECT_NE(chart.find(">exact (CPU reference)</text>"), std::string::npos);
}

TEST(TradeCommand, BadListsExitTwoNamingTheOption) {
  const std::string dir = test::outputDir();
  for (const std::vector<std::string>& option :
       {std::vector<std::string>{"--layers", "0"}, std::vector<std::string>{"--slices", "33"},
        std::vector<std::string>{"--precision", "double"},
        std::vector<std::string>{"--filter", "gauss"},
        std::vector<std::string>{"--method", "maps"}}) {
    std::vector<std::string> command{test::ivshadowExe(), "trade",
                                     test::scenesDir() + "/coloured_shadows.iv", "-o", dir};
    command.insert(command.end(), option.begin(), option.end());
    const test::ProcessResult result = run(command);
    EXPECT_EQ(result.exitCode, 2) << option[0];
    EXPECT_NE(result.err.find(option[0]), std::string::npos) << result.err;
  }
  // Every value the option accepts is listed, not the first and the last.
  const test::ProcessResult method =
      run({test::ivshadowExe(), "trade", test::scenesDir() + "/coloured_shadows.iv", "-o", dir,
           "--method", "rays,maps"});
  EXPECT_EQ(method.err,
            "--method maps: error: expected one or more of map, rays, volumes, opacity or tracer, "
            "comma-separated\n");
  const test::ProcessResult filter =
      run({test::ivshadowExe(), "trade", test::scenesDir() + "/coloured_shadows.iv", "-o", dir,
           "--filter", "gauss"});
  EXPECT_NE(filter.err.find("expected one or more of none, bilinear or pcf"), std::string::npos)
      << filter.err;
  const test::ProcessResult noLight =
      run({test::ivshadowExe(), "trade", test::scenesDir() + "/lit_plane.iv", "-o", dir});
  EXPECT_EQ(noLight.exitCode, 2);
  EXPECT_NE(noLight.err.find("lit_plane.iv"), std::string::npos) << noLight.err;
  EXPECT_FALSE(test::fileExists(dir + "/trade.csv"));
}

// -o names a directory: a file there (or on the way to it), or no name at all, is refused at
// once with exit 2, naming the path and what was expected, not with a raw filesystem error and
// exit 1 after the reference was rendered.
TEST(TradeCommand, AnOutputThatCannotBeADirectoryExitsTwoNamingIt) {
  const std::string file = test::writeOutputFile("a-file", "not a directory\n");
  const std::string what = "-o expects a directory for trade.csv, trade.svg and reference.png";
  const struct {
    std::string output;
    std::string expected;
  } cases[] = {
      {file, file + ": error: " + what + ", but " + file + " is a file\n"},
      {file + "/trade",
       file + "/trade: error: " + what + ", but " + file + " (in " + file + "/trade) is a file\n"},
      {"",
       "-o '': error: expected a directory for trade.csv, trade.svg and reference.png, got an "
       "empty name\n"},
  };
  for (const auto& c : cases) {
    const test::ProcessResult result =
        run({test::ivshadowExe(), "trade", test::scenesDir() + "/coloured_shadows.iv", "-o",
             c.output, "--method", "rays", "--size", "32x24", "--frames", "1"});
    EXPECT_EQ(result.exitCode, 2) << result.err;
    EXPECT_EQ(result.err, c.expected);
  }
  EXPECT_EQ(test::readText(file), "not a directory\n");
}

TEST(TradeCommand, ASizeBeyondMemoryIsRefusedBeforeTheReference) {
  const std::string dir = test::outputDir() + "/out";
  // The reference (34) and the traced render (12 + 370, and 80 + 80 for its group's peel
  // targets and fragment lists) in one process: 576 bytes a pixel.
  if (double(MemoryBudget::available()) > 576.0 * 16384.0 * 16384.0)
    GTEST_SKIP() << "this machine has the memory";
  const test::ProcessResult result =
      run({test::ivshadowExe(), "trade", test::scenesDir() + "/coloured_shadows.iv", "-o", dir,
           "--size", "16384x16384"});
  EXPECT_EQ(result.exitCode, 2) << result.err;
  EXPECT_NE(result.err.find("--size 16384x16384: error: the trade"), std::string::npos)
      << result.err;
  EXPECT_NE(result.err.find("576 bytes per pixel"), std::string::npos) << result.err;
  EXPECT_FALSE(test::fileExists(dir)) << "bad input makes no directory";
}

}  // namespace
}  // namespace ivshadow
