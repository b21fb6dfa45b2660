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

// The transparency type SoQt's viewers render with (SoQtViewer's SoGLRenderAction reports
// BLEND): `ivshadow render --transparency` with it draws what the viewer shows.
constexpr const char* kViewerTransparency = "BLEND";

// Runs the viewer with `arguments`, which make it save a screenshot to `shot`, and returns the
// screenshot (an empty image when the viewer failed or wrote none). `result` receives the
// run's exit status and output.
Image viewerScreenshot(const std::vector<std::string>& arguments, const std::string& shot,
                       ProcessResult& result);

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
