#pragma once

#include <chrono>
#include <string>

namespace ivshadow {

// Writes go to a temporary file beside `path`; commit() renames it over `path`, keeping the
// mode of a file it replaces (and, for root, its owner). A file that is not committed (an
// error, an exception, Ctrl-C handled by the caller) is removed, so no partial output is ever
// left under the final name. A symbolic link is followed and its
// target replaced; a device, pipe or socket (`/dev/null`, `/dev/stdout`) is written to in
// place, since replacing it (as root) would destroy it; a FIFO that no process opens for
// reading within kFifoReaderWait is refused (InputError) rather than waited on for good.
class AtomicFile {
 public:
  // How long a FIFO output is waited on for a reader before it is refused.
  static constexpr std::chrono::seconds kFifoReaderWait{5};

  explicit AtomicFile(std::string path);
  ~AtomicFile();
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;

  // The file to write: the temporary, or the output itself where it is written in place.
  const std::string& temporaryPath() const { return temporary_; }
  bool inPlace() const { return writeThrough_; }
  // Throws std::runtime_error when the rename fails.
  void commit();

  // Throws InputError when `path` cannot be created (missing directory, no permission), or is
  // an existing file the user could not write in place (for root: one without any write bit),
  // so bad output paths are reported before any work is done.
  static void checkWritable(const std::string& path, const std::string& what);
  // The file `path` finally names: symbolic links followed, even to a file not there yet.
  static std::string finalTarget(const std::string& path);
  // Whether `path` is an existing device, pipe or socket, which is written in place.
  static bool writesInPlace(const std::string& path);

 private:
  std::string path_;
  std::string temporary_;
  bool committed_ = false;
  bool writeThrough_ = false;
  int fifoHold_ = -1;  // a FIFO output held open while it is written (see the constructor)
};

// Writes `text` to `path` through an AtomicFile.
void writeTextFileAtomically(const std::string& path, const std::string& text);

}  // namespace ivshadow
