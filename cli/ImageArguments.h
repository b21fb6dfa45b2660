#pragma once

#include <string>

namespace ivshadow {

// Refuses an image output (`render -o`, `reference -o`, `compare --diff`) that names an
// existing directory, saying so: the format check alone reports a type '(no extension)'.
void checkImageOutput(const std::string& option, const std::string& path);

// What a command that renders `scene` into the picture `-o output`, and into the optional
// file `option path` ("" when not asked for), checks before it reads the scene: no output
// names the scene or the other output, the picture is a file of a format it writes, and the
// picture can be written (the caller checks the second file in turn).
void checkPictureOutputs(const std::string& scene, const std::string& output,
                         const std::string& option, const std::string& path);

// Refuses an input picture of a type compare cannot read (a scene, `compare scene.iv x.png`)
// as an input, with the types it reads: the format check alone says it cannot *write* them.
void checkImageInput(const std::string& argument, const std::string& path);

}  // namespace ivshadow
