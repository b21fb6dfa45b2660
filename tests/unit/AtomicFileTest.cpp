#include "image/AtomicFile.h"
#include "scene/InputError.h"
#include "tests/support/TestSupport.h"

#include <sys/stat.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <thread>

namespace ivshadow {
namespace {

namespace fs = std::filesystem;

std::string contents(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

TEST(AtomicFile, ASymbolicLinkStaysALinkAndItsTargetIsReplaced) {
  const std::string dir = test::outputDir();
  std::ofstream(dir + "/target.png") << "old";
  fs::create_symlink("target.png", dir + "/link.png");
  writeTextFileAtomically(dir + "/link.png", "new");
  EXPECT_TRUE(fs::is_symlink(fs::symlink_status(dir + "/link.png")));
  EXPECT_EQ(contents(dir + "/target.png"), "new");
  // No temporary file is left beside either.
  int files = 0;
  for (auto it = fs::directory_iterator(dir); it != fs::directory_iterator(); ++it) ++files;
  EXPECT_EQ(files, 2);
}

// Run as root (as CI runs) a rename over /dev/null replaced the device with a regular file.
// A name the file system cannot take (its temporary name included: a dot, ".tmp" and the
// process id more) is refused before any work, as bad input, rather than failing after it.
TEST(AtomicFile, ANameTooLongForTheFileSystemIsRefusedBeforeTheWork) {
  const std::string dir = test::outputDir();
  const std::string tooLong = dir + "/" + std::string(300, 'a') + ".png";
  const std::string error =
      test::inputErrorOf([&] { AtomicFile::checkWritable(tooLong, "the image"); });
  EXPECT_NE(error.find("its name has 304 characters, more than the"), std::string::npos) << error;
  // 200 characters fit (NAME_MAX is 255 on Linux's file systems).
  const std::string fits = dir + "/" + std::string(196, 'b') + ".png";
  EXPECT_EQ(test::inputErrorOf([&] { AtomicFile::checkWritable(fits, "the image"); }), "");
}

TEST(AtomicFile, DevicesAreWrittenInPlaceNeverReplaced) {
  AtomicFile::checkWritable("/dev/null", "the image");
  writeTextFileAtomically("/dev/null", "discarded");
  struct stat info {};
  ASSERT_EQ(::stat("/dev/null", &info), 0);
  EXPECT_TRUE(S_ISCHR(info.st_mode));
  // A pipe too: what is written arrives at the reader.
  const std::string fifo = test::outputDir() + "/pipe";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  std::string received;
  std::thread reader([&] { received = contents(fifo); });
  writeTextFileAtomically(fifo, "through");
  reader.join();
  EXPECT_EQ(received, "through");
  EXPECT_TRUE(fs::is_fifo(fifo));
}

TEST(AtomicFile, TheInputIsNeverAnOutputWhateverTheSpelling) {
  const std::string dir = test::outputDir();
  std::ofstream(dir + "/scene.iv") << "#Inventor V2.1 ascii\n";
  fs::create_symlink("scene.iv", dir + "/alias.iv");
  for (const std::string output : {dir + "/scene.iv", dir + "/./scene.iv", dir + "/alias.iv"}) {
    try {
      AtomicFile::checkNotInput(output, dir + "/scene.iv", "the image");
      ADD_FAILURE() << output << " was accepted as an output";
    } catch (const InputError& error) {
      EXPECT_EQ(
          std::string(error.what()),
          output + ": error: cannot write the image over the input file " + dir + "/scene.iv");
    }
  }
  AtomicFile::checkNotInput(dir + "/other.png", dir + "/scene.iv", "the image");
}

}  // namespace
}  // namespace ivshadow
