#include "image_files/AtomicFile.h"

#include "scene/InputError.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <thread>

namespace ivshadow {
namespace {

std::string temporaryNameFor(const std::string& path) {
  const std::filesystem::path target(path);
  std::string name = "." + target.filename().string() + ".tmp" + std::to_string(::getpid());
  return (target.parent_path() / name).string();
}

// The file a path finally names: a symbolic link is followed (a rename over the link would
// replace the link with a file and leave its target as it was).
std::filesystem::path followLinks(const std::filesystem::path& path) {
  namespace fs = std::filesystem;
  fs::path current = path;
  std::error_code ec;
  // Linux gives up after 40 links (ELOOP); so does this.
  for (int i = 0; i < 40 && fs::is_symlink(fs::symlink_status(current, ec)); ++i) {
    const fs::path next = fs::read_symlink(current, ec);
    if (ec) break;
    current = next.is_absolute() ? next : current.parent_path() / next;
  }
  return current;
}

// A device, a pipe or a socket that already exists: written to in place (`-o /dev/null`,
// `-o /dev/stdout`), never replaced by a renamed file.
bool writesThrough(const std::filesystem::path& target) {
  std::error_code ec;
  const auto status = std::filesystem::status(target, ec);
  return !ec && std::filesystem::exists(status) && !std::filesystem::is_regular_file(status) &&
         !std::filesystem::is_directory(status);
}

// A file the user could not write in place is not replaced either, although the rename only
// needs the directory: replacing it would undo its owner's choice (a read-only reference
// picture) and hand the file to this user. Root may write any file, so for root the mode
// decides: a file nobody may write (0444) is refused, the rest are replaced keeping their
// owner and mode (AtomicFile::commit).
void checkReplaceable(const std::string& path, const std::filesystem::path& target,
                      const std::string& what) {
  struct stat info {};
  if (::stat(target.c_str(), &info) != 0 || !S_ISREG(info.st_mode)) return;
  char mode[8];
  std::snprintf(mode, sizeof mode, "%04o", unsigned(info.st_mode & 07777));
  const bool root = ::geteuid() == 0;
  if (root ? (info.st_mode & (S_IWUSR | S_IWGRP | S_IWOTH)) == 0
           : ::faccessat(AT_FDCWD, target.c_str(), W_OK, AT_EACCESS) != 0)
    throw InputError(path + ": error: cannot write " + what + ": the file is read-only (mode " +
                     mode + ", owner uid " + std::to_string(info.st_uid) + "); it is not replaced");
}

}  // namespace

AtomicFile::AtomicFile(std::string path) : path_(followLinks(path).string()) {
  writeThrough_ = writesThrough(path_);
  temporary_ = writeThrough_ ? path_ : temporaryNameFor(path_);
  // Opening a FIFO for writing waits for a reader, and open() restarts after a signal
  // handler: with none, the command hung for good, deaf to SIGTERM. Opened without waiting,
  // it is tried for kFifoReaderWait (a reader started beside the command may open it a little
  // later), then refused; once open it is held until the writes are done, so that the reader
  // sees no end of file between this probe and the writer's own open().
  struct stat status {};
  if (writeThrough_ && ::stat(path_.c_str(), &status) == 0 && S_ISFIFO(status.st_mode)) {
    const auto until = std::chrono::steady_clock::now() + kFifoReaderWait;
    while ((fifoHold_ = ::open(path_.c_str(), O_WRONLY | O_NONBLOCK | O_CLOEXEC)) < 0 &&
           errno == ENXIO && std::chrono::steady_clock::now() < until)
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    if (fifoHold_ < 0 && errno == ENXIO)
      throw InputError(path + ": error: a FIFO that no process opened for reading within " +
                       std::to_string(kFifoReaderWait.count()) + " s");
  }
}

AtomicFile::~AtomicFile() {
  if (!committed_ && !writeThrough_) std::remove(temporary_.c_str());
  if (fifoHold_ >= 0) ::close(fifoHold_);
}

void AtomicFile::commit() {
  if (writeThrough_) {
    committed_ = true;
    return;
  }
  // The file replaced keeps its mode (a private 0600 picture stays private) and, where this
  // user may give it (root), its owner and group.
  struct stat existing {};
  if (::stat(path_.c_str(), &existing) == 0 && S_ISREG(existing.st_mode)) {
    // Only root may give a file to another owner: for others it stays theirs, as the check
    // allowed (they could write it), so a failure here is no error.
    const int given = ::chown(temporary_.c_str(), existing.st_uid, existing.st_gid);
    static_cast<void>(given);
    ::chmod(temporary_.c_str(), existing.st_mode & 07777);
  }
  if (std::rename(temporary_.c_str(), path_.c_str()) != 0) {
    throw std::runtime_error(path_ + ": error: cannot write: " + std::strerror(errno));
  }
  committed_ = true;
}

void AtomicFile::checkWritable(const std::string& path, const std::string& what) {
  namespace fs = std::filesystem;
  if (path.empty()) throw InputError(what + ": error: empty file name");
  const fs::path target = followLinks(path);
  if (writesThrough(target)) {
    if (::access(target.c_str(), W_OK) != 0)
      throw InputError(path + ": error: cannot write " + what + ": " + std::strerror(errno));
    return;
  }
  const fs::path directory = target.has_parent_path() ? target.parent_path() : fs::path(".");
  std::error_code ec;
  if (!fs::is_directory(directory, ec)) {
    throw InputError(path + ": error: cannot write " + what + ": directory '" + directory.string() +
                     "' does not exist");
  }
  if (fs::is_directory(target, ec)) {
    throw InputError(path + ": error: cannot write " + what + ": it is a directory");
  }
  if (::access(directory.c_str(), W_OK) != 0) {
    throw InputError(path + ": error: cannot write " + what + ": " + std::strerror(errno));
  }
  checkReplaceable(path, target, what);
  // The file is written under its temporary name first, which is longer: both must fit the
  // directory's file system (ENAMETOOLONG after the work would lose it).
  const long nameMax = ::pathconf(directory.c_str(), _PC_NAME_MAX);
  const std::size_t temporaryLength =
      std::filesystem::path(temporaryNameFor(target.string())).filename().string().size();
  if (nameMax > 0 && temporaryLength > std::size_t(nameMax)) {
    const std::size_t longest =
        std::size_t(nameMax) - (temporaryLength - target.filename().string().size());
    throw InputError(path + ": error: cannot write " + what + ": its name has " +
                     std::to_string(target.filename().string().size()) +
                     " characters, more than the " + std::to_string(longest) +
                     " that can be written there");
  }
}

std::string AtomicFile::finalTarget(const std::string& path) {
  return followLinks(path).string();
}

bool AtomicFile::writesInPlace(const std::string& path) {
  return writesThrough(followLinks(path));
}

void writeTextFileAtomically(const std::string& path, const std::string& text) {
  AtomicFile file(path);
  {
    std::ofstream out(file.temporaryPath(), std::ios::binary);
    out << text;
    out.close();
    if (!out) throw std::runtime_error(path + ": error: cannot write: " + std::strerror(errno));
  }
  file.commit();
}

}  // namespace ivshadow
