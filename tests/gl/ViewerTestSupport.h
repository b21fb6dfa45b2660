#pragma once

#include "image/Image.h"
#include "tests/support/TestSupport.h"

#include <string>
#include <vector>

namespace ivshadow::test {

// The X server of the viewer suite: IVSHADOW_TEST_DISPLAY, or the display that the CTest
// fixture `xserver` (tests/xserver/xserver.sh) started; empty when there is none.
std::string testDisplay();

// Runs the viewer (or any command) on the suite's Xvfb server (Mesa's GLX draws with
// llvmpipe there); the command's own exit status comes back unchanged. XDG_CONFIG_HOME points
// into the test's output directory, so the viewer's settings never touch the user's.
ProcessResult runOnTestDisplay(const std::vector<std::string>& arguments,
                               const std::vector<std::string>& environment = {});

// Runs the viewer with `arguments`, which make it save a screenshot to `shot`, and returns the
// screenshot. When fewer than `share` of its pixels lie within 2 steps of `expected`, the
// screenshot is taken again, up to kScreenshotAttempts times in all, and the last one is
// returned: the viewer's scripted screenshot of plain Coin transparency sometimes shows its
// transparent shapes blended twice (docs/KNOWN_ISSUES.md; measured on a loaded two-core
// machine: 12 of 24 screenshots of coloured_shadows.iv with the group off, always the same
// 3.76 % of the pixels up to 40 steps off, with or without the light dragger). Eight attempts
// bring the chance of eight bad pictures in a row to 1/256 at that worst rate; a viewer
// that really draws differently gives eight such screenshots and fails the caller's comparison
// all the same. `result` receives the (last) run's exit status and output.
constexpr int kScreenshotAttempts = 8;
Image viewerScreenshot(const std::vector<std::string>& arguments, const std::string& shot,
                       const Image& expected, double share, ProcessResult& result);

// The whole content of a file ("" when it cannot be read).
std::string readText(const std::string& path);

// Share of pixels whose colour channels all lie within `tolerance` of the other image's.
double shareWithin(const Image& a, const Image& b, int tolerance);

// Share of pixels bright enough to be scene rather than the black background.
double shareLit(const Image& image);

// Expects at least `share` of the pixels of `actual` within `tolerance` steps of `expected`
// (same size required); on failure writes actual.png, expected.png and diff.png to
// outputDir() and names them in the failure.
void expectMostlyEqual(const Image& actual, const Image& expected, int tolerance, double share,
                       const std::string& what);

}  // namespace ivshadow::test
