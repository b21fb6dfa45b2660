#include "cli/ImageArguments.h"

#include "image_files/AtomicFile.h"
#include "image_files/CommandPaths.h"
#include "image_files/ImageFile.h"
#include "scene/InputError.h"

#include <filesystem>

namespace ivshadow {

void checkImageOutput(const std::string& option, const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw InputError(path + ": error: " + option +
                     " names a directory; expected the name of an image file, e.g. " +
                     (std::filesystem::path(path) / "picture.png").string());
}

void checkPictureOutputs(const std::string& scene, const std::string& output,
                         const std::string& option, const std::string& path) {
  CommandPaths().input("scene", scene).output("-o", output).output(option, path).check();
  checkImageOutput("-o", output);
  imageFormatFor(output);
  AtomicFile::checkWritable(output, "the image");
}

void checkImageInput(const std::string& argument, const std::string& path) {
  try {
    imageFormatFor(path);
  } catch (const InputError&) {
    // The types readImage reads are those imageFormatFor knows (image_files/ImageFile.h).
    const std::string extension = std::filesystem::path(path).extension().string();
    throw InputError(path + ": error: cannot read images of type '" +
                     (extension.empty() ? std::string("(no extension)") : extension) + "' (the " +
                     argument + "); compare reads PNG and JPEG: " + kImageExtensions);
  }
}

}  // namespace ivshadow
