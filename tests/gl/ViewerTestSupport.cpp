#include "tests/gl/ViewerTestSupport.h"

#include "image_files/PngFile.h"

#include <iostream>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <iterator>

namespace ivshadow::test {

std::string testDisplay() {
  if (const char* display = std::getenv("IVSHADOW_TEST_DISPLAY"); display && *display)
    return display;
  std::ifstream file(std::string(IVSHADOW_TEST_OUTPUT_DIR) + "/xserver/display");
  std::string display;
  std::getline(file, display);
  return display;
}

ProcessResult runOnTestDisplay(const std::vector<std::string>& arguments,
                               const std::vector<std::string>& environment) {
  const std::string display = testDisplay();
  if (display.empty()) {
    ADD_FAILURE() << "no test X server: run the viewer tests through ctest (fixture xserver, "
                     "tests/xserver/xserver.sh) or set IVSHADOW_TEST_DISPLAY";
    return ProcessResult();
  }
  std::vector<std::string> env = {"DISPLAY=" + display,
                                  "XDG_CONFIG_HOME=" + outputDir() + "/config"};
  env.insert(env.end(), environment.begin(), environment.end());
  return run(arguments, env);
}

double shareWithin(const Image& a, const Image& b, int tolerance) {
  int close = 0;
  for (int y = 0; y < a.height(); ++y)
    for (int x = 0; x < a.width(); ++x) {
      int worst = 0;
      for (int c = 0; c < 3; ++c)
        worst = std::max(worst, std::abs(a.pixel(x, y)[c] - b.pixel(x, y)[c]));
      close += worst <= tolerance ? 1 : 0;
    }
  return double(close) / double(a.width() * a.height());
}

double shareLit(const Image& image) {
  int lit = 0;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x)
      lit += image.pixel(x, y)[0] + image.pixel(x, y)[1] + image.pixel(x, y)[2] > 60 ? 1 : 0;
  return double(lit) / double(image.width() * image.height());
}

void expectMostlyEqual(const Image& actual, const Image& expected, int tolerance, double share,
                       const std::string& what) {
  ASSERT_EQ(actual.width(), expected.width()) << what;
  ASSERT_EQ(actual.height(), expected.height()) << what;
  const double measured = shareWithin(actual, expected, tolerance);
  if (measured >= share) return;
  const std::string files = compareWithExpectation(
      actual,
      [&expected](int x, int y) {
        Expectation e;
        e.checked = true;
        for (int c = 0; c < 3; ++c) e.rgb[c] = expected.pixel(x, y)[c];
        return e;
      },
      tolerance);
  ADD_FAILURE() << what << ": " << measured * 100.0 << " % of the pixels within " << tolerance
                << " steps, expected at least " << share * 100.0 << " %. " << files;
}

Image viewerScreenshot(const std::vector<std::string>& arguments, const std::string& shot,
                       ProcessResult& result) {
  result = runOnTestDisplay(arguments);
  if (result.exitCode != 0 || !fileExists(shot)) return Image();
  return readPng(shot);
}

}  // namespace ivshadow::test
