#include "image_files/AtomicFile.h"
#include "image_files/CommandPaths.h"
#include "scene/InputError.h"
#include "tests/support/TestSupport.h"

#include <sys/stat.h>
#include <unistd.h>

#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <thread>

namespace ivshadow {
namespace {

namespace fs = std::filesystem;

const auto contents = test::readText;

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

// Rendering over a read-only file owned by someone else replaced it, with a new owner and
// mode 0644: the directory allowed the rename. A file the user could not write in place is
// refused (for root, who may write anything, one without any write bit), and a file that is
// replaced keeps its mode, and for root its owner.
TEST(AtomicFile, AFileThatMayNotBeWrittenIsRefusedAndAReplacedOneKeepsItsOwnerAndMode) {
  const std::string dir = test::outputDir();
  const std::string locked = dir + "/locked.png";
  std::ofstream(locked) << "reference picture";
  ASSERT_EQ(::chmod(locked.c_str(), 0444), 0);
  const std::string error =
      test::inputErrorOf([&] { AtomicFile::checkWritable(locked, "the image"); });
  EXPECT_EQ(
      error.rfind(locked + ": error: cannot write the image: the file is read-only (mode 0444", 0),
      0u)
      << error;
  EXPECT_EQ(contents(locked), "reference picture");
  // Through a link too.
  fs::create_symlink("locked.png", dir + "/link.png");
  EXPECT_NE(test::inputErrorOf([&] { AtomicFile::checkWritable(dir + "/link.png", "the image"); }),
            "");

  const std::string shared = dir + "/shared.png";
  std::ofstream(shared) << "old";
  ASSERT_EQ(::chmod(shared.c_str(), 0640), 0);
  const bool root = ::geteuid() == 0;
  // As root the file is given to another user first (65534: nobody), whose file root writes.
  if (root) ASSERT_EQ(::chown(shared.c_str(), 65534, 65534), 0);
  EXPECT_EQ(test::inputErrorOf([&] { AtomicFile::checkWritable(shared, "the image"); }), "");
  writeTextFileAtomically(shared, "new");
  EXPECT_EQ(contents(shared), "new");
  struct stat info {};
  ASSERT_EQ(::stat(shared.c_str(), &info), 0);
  EXPECT_EQ(info.st_mode & 07777, 0640u);
  if (root) {
    EXPECT_EQ(info.st_uid, 65534u);
    EXPECT_EQ(info.st_gid, 65534u);
  }
}

// Issue 35: an output that is a FIFO with no reader blocked the command forever (and SIGTERM
// with it: open() restarts after the handler). Refused after kFifoReaderWait; with a reader
// (here one that opens it a moment later), written whole, the reader seeing no end of file
// before the writer is done.
TEST(AtomicFile, AFifoNobodyReadsIsRefusedAndOneBeingReadIsWrittenWhole) {
  const std::string fifo = test::outputDir() + "/out.fifo";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  EXPECT_THROW(writeTextFileAtomically(fifo, "lost"), InputError);
  std::string received;
  std::thread reader([&] {
    std::ifstream in(fifo, std::ios::binary);
    received.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  });
  const std::string text(100000, 'x');
  writeTextFileAtomically(fifo, text);
  reader.join();
  EXPECT_EQ(received.size(), text.size());
}

TEST(CommandPaths, TheInputIsNeverAnOutputWhateverTheSpelling) {
  const std::string dir = test::outputDir();
  std::ofstream(dir + "/scene.iv") << "#Inventor V2.1 ascii\n";
  fs::create_symlink("scene.iv", dir + "/alias.iv");
  fs::create_symlink(dir + "/missing.png", dir + "/dangling.png");
  for (const std::string output :
       {dir + "/scene.iv", dir + "/./scene.iv", dir + "/alias.iv",
        dir + "/../" + fs::path(dir).filename().string() + "/scene.iv"}) {
    const std::string error = test::inputErrorOf(
        [&] { CommandPaths().input("scene", dir + "/scene.iv").output("-o", output).check(); });
    EXPECT_EQ(error, output + ": error: -o names the input scene (" + dir +
                         "/scene.iv); an output never replaces an input");
  }
  // Files not there yet compare by their names, a dangling link by the file it would make.
  EXPECT_TRUE(CommandPaths::sameFile(dir + "/new.png", dir + "/sub/../new.png"));
  EXPECT_TRUE(CommandPaths::sameFile(dir + "/dangling.png", dir + "/missing.png"));
  EXPECT_FALSE(CommandPaths::sameFile(dir + "/new.png", dir + "/New.png"));
  EXPECT_EQ(test::inputErrorOf([&] {
              CommandPaths()
                  .input("scene", dir + "/scene.iv")
                  .output("-o", dir + "/other.png")
                  .output("--stats", "")
                  .check();
            }),
            "");
}

TEST(CommandPaths, TwoOutputsNeverShareAFileButMayShareADevice) {
  const std::string dir = test::outputDir();
  const std::string error = test::inputErrorOf([&] {
    CommandPaths().output("-o", dir + "/x.png").output("--stats", dir + "/./x.png").check();
  });
  EXPECT_EQ(error, dir + "/./x.png: error: -o and --stats name the same file (" + dir +
                       "/x.png); each output needs a file of its own");
  fs::create_symlink("x.png", dir + "/y.png");
  EXPECT_NE(test::inputErrorOf([&] {
              CommandPaths().output("-o", dir + "/y.png").output("--pfm", dir + "/x.png").check();
            }),
            "")
      << "through a link not there yet";
  EXPECT_EQ(test::inputErrorOf([&] {
              CommandPaths().output("-o", "/dev/null").output("--stats", "/dev/null").check();
            }),
            "");
}

}  // namespace
}  // namespace ivshadow
