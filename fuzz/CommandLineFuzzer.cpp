// libFuzzer harness: `ivshadow` command lines as users type them (one argument per line of
// the input), parsed by the command line itself (cli/CommandLine) and, for the commands that
// finish in milliseconds at small sizes (render, reference, compare, variants-merge), run:
// paths, outputs that name inputs or each other, sizes, counts, --set texts. The run happens
// in a scratch folder holding a small scene and two pictures; an argument naming anything
// outside it (a '/' anywhere), a size over 64 x 64 or counts that make a run slow are left
// out, so the harness measures the command line, not the renderer's speed. view, trade and
// variants (windows, minutes, child processes) are parsed only.
#include "cli/CommandLine.h"
#include "fuzz/FuzzInput.h"
#include "image/Image.h"
#include "image_files/PngFile.h"

#include <unistd.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>
#include <vector>

namespace {

const char kScene[] =
    "#Inventor V2.1 ascii\n"
    "TransparentShadowGroup {\n"
    "  DEF Lamp DeepShadowLight { location 0 0 3 }\n"
    "  Coordinate3 { point [ -2 -2 0, 2 -2 0, 2 2 0, -2 2 0 ] }\n"
    "  FaceSet { numVertices 4 }\n"
    "  DEF Glass Material { diffuseColor 1 0 0 transparency 0.5 }\n"
    "  Translation { translation 0 0 1 }\n"
    "  Cube { width 1 height 1 depth 0.1 }\n"
    "}\n";

// The scratch folder, made once per process and entered; each input starts from the same
// files (an output that replaced one is written back).
void enterScratch() {
  namespace fs = std::filesystem;
  static const std::string dir = [] {
    const std::string made = "/dev/shm/ivshadow-cli-fuzz-" + std::to_string(::getpid());
    fs::create_directories(made);
    if (::chdir(made.c_str()) != 0) std::abort();
    return made;
  }();
  // What the last input wrote goes: the folder holds only these files at each start.
  for (const auto& entry : fs::directory_iterator(dir)) fs::remove_all(entry.path());
  std::ofstream("a.iv") << kScene;
  // Two pictures to compare, a pixel apart.
  ivshadow::Image picture(2, 2);
  ivshadow::writePng("b.png", picture);
  picture.pixel(1, 1)[0] = 200;
  ivshadow::writePng("c.png", picture);
}

// Whether a run of this command line stays small and inside the scratch folder (a command
// that draws must name a small --size: its default is 800 x 600).
bool quickAndLocal(const std::vector<std::string>& arguments, bool draws) {
  bool sized = false;
  static const std::regex size(R"((\d+)\D*[xX]\D*(\d+))");
  // "--bounce=65536" is "--bounce" "65536" to CLI11.
  std::vector<std::string> split;
  for (const std::string& argument : arguments) {
    const std::size_t equals =
        argument.rfind("--", 0) == 0 ? argument.find('=') : std::string::npos;
    split.push_back(argument.substr(0, equals));
    if (equals != std::string::npos) split.push_back(argument.substr(equals + 1));
  }
  for (std::size_t i = 0; i < split.size(); ++i) {
    const std::string& a = split[i];
    if (a.find('/') != std::string::npos || a.find("..") != std::string::npos) return false;
    std::smatch m;
    if (std::regex_search(a, m, size) &&
        (m[1].length() > 3 || m[2].length() > 3 || std::stoi(m[1]) * std::stoi(m[2]) > 64 * 64))
      return false;
    sized = sized || (a == "--size" && i + 1 < split.size());
    const bool count = a == "--frames" || a == "--bounce" || a == "--threads";
    if (count && i + 1 < split.size() &&
        (split[i + 1].size() > 2 || std::atoi(split[i + 1].c_str()) > 4))
      return false;
  }
  return sized || !draws;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  ivshadow::fuzz::initOnce();
  enterScratch();
  std::vector<std::string> arguments{"ivshadow"};
  std::string current;
  for (std::size_t i = 0; i < size; ++i) {
    if (data[i] == '\n') {
      arguments.push_back(current);
      current.clear();
    } else if (data[i] != '\0') {
      current += char(data[i]);
    }
  }
  if (!current.empty()) arguments.push_back(current);
  if (arguments.size() > 24) return 0;
  std::vector<char*> argv;
  for (std::string& argument : arguments) argv.push_back(argument.data());
  argv.push_back(nullptr);

  ivshadow::CommandLine commandLine;
  if (commandLine.parse(int(arguments.size()), argv.data())) return 0;
  const std::string command = commandLine.command();
  const bool runs = command == "render" || command == "reference" || command == "compare" ||
                    command == "variants-merge";
  if (runs && quickAndLocal(arguments, command == "render" || command == "reference")) {
    const int status = commandLine.run();
    // The contract: success, bad input or no GL; anything else (1) is a finding to look at,
    // printed rather than stopped at (a device full or a signal are 1 by design).
    if (status != 0 && status != 2 && status != 3)
      std::fprintf(stderr, "CommandLineFuzzer: exit %d\n", status);
  }
  return 0;
}
