#include "image_files/OutputFiles.h"

#include "image_files/AtomicFile.h"
#include "image_files/ImageFile.h"

#include <cerrno>
#include <csignal>
#include <cstring>
#include <fstream>
#include <memory>
#include <stdexcept>

namespace ivshadow {

void OutputFiles::add(const std::string& path, Writer write) {
  outputs_.push_back({path, std::move(write)});
}

void OutputFiles::addImage(const std::string& path, const Image& image) {
  add(path, [path, &image](const std::string& file) { writeImageTo(file, path, image); });
}

void OutputFiles::addText(const std::string& path, std::string text) {
  add(path, [path, text = std::move(text)](const std::string& file) {
    std::ofstream out(file, std::ios::binary);
    out << text;
    out.close();
    if (!out) throw std::runtime_error(path + ": error: cannot write: " + std::strerror(errno));
  });
}

bool OutputFiles::commit(const std::atomic<bool>* cancel) {
  std::vector<std::unique_ptr<AtomicFile>> files(outputs_.size());
  // Each output's AtomicFile is made just before it is written: a FIFO waits there for its
  // reader, after the temporaries are on disk.
  for (bool inPlace : {false, true})
    for (std::size_t i = 0; i < outputs_.size(); ++i) {
      if (AtomicFile::writesInPlace(outputs_[i].path) != inPlace) continue;
      files[i] = std::make_unique<AtomicFile>(outputs_[i].path);
      outputs_[i].write(files[i]->temporaryPath());
    }
  // The files not committed are removed with their AtomicFile.
  if (cancel != nullptr && cancel->load()) return false;
  for (const std::unique_ptr<AtomicFile>& file : files) file->commit();
  return true;
}

namespace {

volatile std::sig_atomic_t heldSignal = 0;

void holdSignal(int signal) {
  heldSignal = signal;
}

}  // namespace

void OutputFiles::commitWhole() {
  constexpr int kSignals[] = {SIGINT, SIGTERM, SIGHUP};
  struct sigaction hold {};
  hold.sa_handler = holdSignal;
  sigemptyset(&hold.sa_mask);
  struct sigaction previous[3];
  heldSignal = 0;
  for (int i = 0; i < 3; ++i) sigaction(kSignals[i], &hold, &previous[i]);
  const auto deliver = [&] {
    for (int i = 0; i < 3; ++i) sigaction(kSignals[i], &previous[i], nullptr);
    if (heldSignal != 0) std::raise(heldSignal);
  };
  try {
    commit();
  } catch (...) {
    deliver();
    throw;
  }
  deliver();
}

}  // namespace ivshadow
