#pragma once

#include "image/Image.h"
#include "image_files/ImageComparison.h"
#include "tests/support/ShadowMethodNames.h"

#include <array>
#include <functional>
#include <string>
#include <vector>

class SoNode;

namespace ivshadow::test {

// Sets `field` (e.g. "renderer RASTER") on every SoTransparentShadowGroup under `root`: the
// tests that mean GL's path pin it, since the default, AUTO, traces on a software rasteriser.
void setOnEveryGroup(SoNode* root, const std::string& field);

// Paths fixed at build time by tests/CMakeLists.txt.
std::string scenesDir();
std::string ivshadowExe();
std::string viewerExe();
// A fresh, empty directory for the current test's files:
// <build>/test-output/<suite>.<test>/.
std::string outputDir();
// Writes `bytes` as they are to outputDir()/`name` and returns its path.
std::string writeOutputFile(const std::string& name, const std::string& bytes);
// The whole content of a file ("" when it cannot be read).
std::string readText(const std::string& path);

struct ProcessResult {
  int exitCode = -1;
  std::string out;
  std::string err;
};
// Runs `arguments` (no shell) and captures its exit status, stdout and stderr.
ProcessResult run(const std::vector<std::string>& arguments,
                  const std::vector<std::string>& environment = {});

// Starts `arguments` without waiting, stdout and stderr to the files named; returns its pid,
// or -1 when it could not be started. waitForProcess returns its exit status as run() does.
int startProcess(const std::vector<std::string>& arguments,
                 const std::vector<std::string>& environment, const std::string& outPath,
                 const std::string& errPath);
int waitForProcess(int pid);

bool fileExists(const std::string& path);

// Interrupts a command while it writes its outputs: `arguments` name the FIFO `fifo` as an
// output, which the command writes in place after its other outputs' temporaries, and whose
// opening blocks until a reader comes. Once a file whose name starts with `.` appears in
// `dir` (a temporary; 30 s at most), `signal` is sent; then the FIFO is opened for reading so
// that the command can go on. Returns its exit status as waitForProcess does; its stdout and
// stderr are left in `fifo`.stdout and `fifo`.stderr.
int interruptWhileWriting(const std::vector<std::string>& arguments, const std::string& dir,
                          const std::string& fifo, int signal);

// Names of the files in `dir`, sorted.
std::vector<std::string> filesIn(const std::string& dir);

// The message of the InputError `body` throws, or empty when it throws none (any other
// exception propagates).
std::string inputErrorOf(const std::function<void()>& body);

// Non-empty lines of `text`.
std::vector<std::string> lines(const std::string& text);

// Expected linear RGB in 0..255 for a pixel, or nothing for a pixel that is not checked.
struct Expectation {
  bool checked = false;
  std::array<double, 3> rgb{};
};
using ExpectedImage = std::function<Expectation(int x, int y)>;

// Compares every checked pixel with its expectation; a pixel fails when any channel differs
// by more than `tolerance`. On failure writes actual.png, expected.png and diff.png (failing
// pixels red, passing ones dimmed grey) to outputDir() and returns a message naming them and
// the worst pixel; returns an empty string when every pixel passes.
std::string compareWithExpectation(const Image& actual, const ExpectedImage& expected,
                                   double tolerance);

// Renders `scene` with `ivshadow render` (and `renderArguments`) and with `ivshadow
// reference`, both at `size`, into outputDir() as actual.png and reference.png, and measures
// the first against the second. Writes diff.png there when the PSNR is below `psnrFloor`.
// A command that fails is a test failure, and the comparison is then of empty pictures.
ImageComparison renderAgainstReference(const std::string& scene, const std::string& size,
                                       const std::vector<std::string>& renderArguments,
                                       double psnrFloor);

}  // namespace ivshadow::test
