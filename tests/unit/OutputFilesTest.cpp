// A process that leaves SIGTERM to its default action (the viewer's scripted --screenshot,
// --save-scene, --figures) and is signalled while it writes its outputs must not leave a
// temporary or a partial output behind (issue 35): commitWhole() holds the signal until every
// output is in place, then the process ends as the signal says.
#include "image_files/OutputFiles.h"
#include "tests/support/TestSupport.h"

#include <sys/wait.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <csignal>
#include <filesystem>
#include <fstream>

namespace ivshadow {
namespace {

TEST(OutputFiles, ASignalDuringTheWritesEndsTheProcessWithEveryOutputWhole) {
  const std::string dir = test::outputDir();
  const std::string first = dir + "/first.txt", second = dir + "/second.txt";
  const pid_t child = fork();
  if (child == 0) {
    OutputFiles outputs;
    outputs.add(first, [](const std::string& file) {
      std::ofstream out(file);
      out << "the first half, ";
      std::raise(SIGTERM);  // as if the user's kill came now
      out << "the second half";
    });
    outputs.addText(second, "second");
    outputs.commitWhole();
    _exit(0);  // not reached: the held signal ends the process
  }
  int status = 0;
  ASSERT_EQ(waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFSIGNALED(status)) << status;
  EXPECT_EQ(WTERMSIG(status), SIGTERM);
  EXPECT_EQ(test::readText(first), "the first half, the second half");
  EXPECT_EQ(test::readText(second), "second");
  for (const auto& entry : std::filesystem::directory_iterator(dir))
    EXPECT_EQ(entry.path().filename().string().find(".tmp"), std::string::npos) << entry.path();
}

}  // namespace
}  // namespace ivshadow
