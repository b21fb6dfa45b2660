// `ivshadow view`: ivshadow checks the viewer's options itself, then hands the command line to
// ivshadow-viewer beside it (cli/ViewerProcess.h); it links no Qt of its own.
#include "tests/support/TestSupport.h"

#include <gtest/gtest.h>

#include <filesystem>

namespace ivshadow {
namespace {

TEST(ViewCommand, ABadOptionIsRefusedByIvshadowItself) {
  const test::ProcessResult result = test::run({test::ivshadowExe(), "view", "--size"});
  EXPECT_EQ(result.exitCode, 2);
  EXPECT_EQ(result.err.rfind("ivshadow: error: --size", 0), 0u) << result.err;
}

// A copy of ivshadow in a folder without the viewer (its libraries reached as the build's are,
// through $ORIGIN/../lib): exit 1, naming the path it looked for, rather than a silent success.
TEST(ViewCommand, WithoutTheViewerBesideItSaysWhereItLooked) {
  namespace fs = std::filesystem;
  const fs::path dir = test::outputDir();
  const fs::path built = fs::path(test::ivshadowExe()).parent_path();
  fs::create_directories(dir / "bin");
  fs::copy_file(test::ivshadowExe(), dir / "bin/ivshadow", fs::copy_options::overwrite_existing);
  if (!fs::exists(dir / "lib"))
    fs::create_directory_symlink(fs::canonical(built / "../lib"), dir / "lib");
  const test::ProcessResult result = test::run(
      {(dir / "bin/ivshadow").string(), "view", test::scenesDir() + "/lit_plane.iv"}, {"DISPLAY="});
  EXPECT_EQ(result.exitCode, 1) << result.err;
  EXPECT_NE(
      result.err.find((dir / "bin/ivshadow-viewer").string() + ", which could not be started"),
      std::string::npos)
      << result.err;
}

}  // namespace
}  // namespace ivshadow
