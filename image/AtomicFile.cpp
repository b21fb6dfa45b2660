#include "image/AtomicFile.h"

#include "scene/InputError.h"

#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <stdexcept>

namespace ivshadow {
namespace {

std::string temporaryNameFor(const std::string& path) {
  const std::filesystem::path target(path);
  std::string name = "." + target.filename().string() + ".tmp" + std::to_string(::getpid());
  return (target.parent_path() / name).string();
}

}  // namespace

AtomicFile::AtomicFile(std::string path)
    : path_(std::move(path)), temporary_(temporaryNameFor(path_)) {}

AtomicFile::~AtomicFile() {
  if (!committed_) std::remove(temporary_.c_str());
}

void AtomicFile::commit() {
  if (std::rename(temporary_.c_str(), path_.c_str()) != 0) {
    throw std::runtime_error(path_ + ": error: cannot write: " + std::strerror(errno));
  }
  committed_ = true;
}

void AtomicFile::checkWritable(const std::string& path, const std::string& what) {
  namespace fs = std::filesystem;
  if (path.empty()) throw InputError(what + ": error: empty file name");
  const fs::path target(path);
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
