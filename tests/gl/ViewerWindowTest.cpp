#include "image_files/PngFile.h"
#include "tests/gl/InteractiveViewer.h"
#include "tests/gl/ScreenGrab.h"
#include "tests/gl/ViewerTestSupport.h"
#include "tests/support/TestSupport.h"

#include <gtest/gtest.h>

#include <thread>

namespace ivshadow {
namespace {

using test::InteractiveViewer;
using test::ScreenRect;

// The screens of the suite's X server that no other test draws on (tests/xserver/xserver.sh).
constexpr int kScreen1280 = 1, kScreen1024 = 2, kScreen1920 = 3;
const char* const kTitle = "coloured_shadows.iv - ivshadow viewer";

std::string scene() {
  return test::scenesDir() + "/coloured_shadows.iv";
}

// Grabs the screen until the 3D area shows what `ivshadow render` draws at the area's size
// (frames keep coming while the viewer settles), and expects that. The viewer starts without
// its light dragger, which would be drawn over the scene. Any other picture (a wrong size, a
// cut-off or stale area, the panel) differs. 99.5 % within 2 steps leaves room for a few edge
// pixels.
void expectViewShowsTheHeadlessRender(InteractiveViewer& viewer, const ScreenRect& area) {
  const std::string dir = test::outputDir();
  const std::string size = std::to_string(area.width) + "x" + std::to_string(area.height);
  const std::string path = dir + "/headless.png";
  const test::ProcessResult render =
      test::run({test::ivshadowExe(), "render", scene(), "-o", path, "--size", size,
                 "--transparency", test::kViewerTransparency});
  ASSERT_EQ(render.exitCode, 0) << render.err;
  const Image expected = readPng(path);
  Image view;
  for (int i = 0; i < 120; ++i) {
    view = test::crop(test::grabScreen(viewer.display()), area);
    if (test::shareWithin(view, expected, 2) >= 0.995) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(250));
  }
  test::expectMostlyEqual(view, expected, 2, 0.995,
                          "the 3D area on screen against ivshadow render");
  // The whole screen, for a failure's reader: what was around (or over) the area.
  if (test::shareWithin(view, expected, 2) < 0.995) {
    writePng(dir + "/screen.png", test::grabScreen(viewer.display()));
  }
}

// Opens the viewer as a user does on a screen of screenWidth x screenHeight, with the 3D area
// asked to be 800 x 600, and judges the window as it appears there.
void expectPictureFirst(int screen, int screenWidth, int screenHeight) {
  InteractiveViewer viewer(screen, {scene(), "--size", "800x600", "--no-light-dragger"},
                           test::outputDir() + "/config");
  ASSERT_TRUE(viewer.waitForWindow(kTitle));
  const test::WindowTree tree = viewer.settledTree();
  const ScreenRect view = InteractiveViewer::viewArea(tree);
  const std::vector<int> frame = test::frameExtents(viewer.display(), viewer.windowId());
  const ScreenRect outer = {tree.window.x - frame[0], tree.window.y - frame[2],
                            tree.window.width + frame[0] + frame[1],
                            tree.window.height + frame[2] + frame[3]};
  // The window, its frame included, lies on the screen: nothing of the panel is cut off.
  EXPECT_TRUE(ScreenRect({0, 0, screenWidth, screenHeight}).contains(outer))
      << "window with frame at " << outer.x << "," << outer.y << " " << outer.width << "x"
      << outer.height << " on a " << screenWidth << "x" << screenHeight << " screen";
  // The picture first: the 3D area has more than half of the window's width and of its
  // height (the panel, menus and the examiner's wheels share the rest). The tracker's sliver
  // was 68 of 1518 px.
  EXPECT_GT(2 * view.width, tree.window.width) << view.width << " of " << tree.window.width;
  EXPECT_GT(2 * view.height, tree.window.height) << view.height << " of " << tree.window.height;
  if (screenWidth >= 1280) {
    // Room enough: the examiner (3D area with its wheels and buttons) has the 800 x 600
    // asked for.
    bool asked = false;
    for (const ScreenRect& window : tree.all) {
      asked = asked || (window.width == 800 && window.height == 600 && window.contains(view));
    }
    EXPECT_TRUE(asked) << "no 800x600 examiner around the 3D area " << view.width << "x"
                       << view.height;
  }
  expectViewShowsTheHeadlessRender(viewer, view);
  EXPECT_EQ(viewer.quit(), 0) << viewer.output();
}

TEST(ViewerWindow, PictureFirstOnA1280x1024Screen) {
  expectPictureFirst(kScreen1280, 1280, 1024);
}

TEST(ViewerWindow, PictureFirstOnA1024x768Screen) {
  expectPictureFirst(kScreen1024, 1024, 768);
}

TEST(ViewerWindow, PictureFirstOnA1920x1080Screen) {
  expectPictureFirst(kScreen1920, 1920, 1080);
}

TEST(ViewerWindow, ReopensWithTheGeometryItWasClosedWith) {
  const std::string config = test::outputDir() + "/config";
  test::WindowTree closed;
  {
    InteractiveViewer first(kScreen1920, {scene(), "--no-light-dragger"}, config);
    ASSERT_TRUE(first.waitForWindow(kTitle));
    first.settledTree();
    first.resize(1300, 900);
    closed = first.settledTree();
    ASSERT_EQ(closed.window.width, 1300);
    ASSERT_EQ(closed.window.height, 900);
    ASSERT_EQ(first.quit(), 0) << first.output();
  }
  // Opened without --size, the window takes the geometry it was closed with (Qt's settings
  // in XDG_CONFIG_HOME), and with it the same 3D area.
  InteractiveViewer second(kScreen1920, {scene(), "--no-light-dragger"}, config);
  ASSERT_TRUE(second.waitForWindow(kTitle));
  const test::WindowTree reopened = second.settledTree();
  EXPECT_EQ(reopened.window.width, 1300);
  EXPECT_EQ(reopened.window.height, 900);
  EXPECT_EQ(InteractiveViewer::viewArea(reopened).width, InteractiveViewer::viewArea(closed).width);
  EXPECT_EQ(InteractiveViewer::viewArea(reopened).height,
            InteractiveViewer::viewArea(closed).height);
  EXPECT_EQ(second.quit(), 0) << second.output();
}

// Pixels of the black background (no surface drawn there), which only the camera can change.
std::vector<bool> background(const Image& image) {
  std::vector<bool> mask;
  for (int y = 0; y < image.height(); ++y)
    for (int x = 0; x < image.width(); ++x) {
      const std::uint8_t* p = image.pixel(x, y);
      mask.push_back(p[0] + p[1] + p[2] < 30);
    }
  return mask;
}

TEST(ViewerWindow, CtrlDragMovesTheLightNotTheCameraAndClosingAsksToSaveIt) {
  // The light dragger stays on (as users start the viewer); the camera is brought back until
  // it is in view, so the picture is not the file's.
  InteractiveViewer viewer(kScreen1280, {scene(), "--size", "640x400"},
                           test::outputDir() + "/config");
  ASSERT_TRUE(viewer.waitForWindow(kTitle));
  const ScreenRect view = InteractiveViewer::viewArea(viewer.settledTree());
  const Image before = viewer.steadyGrab(view);
  EXPECT_EQ(viewer.title(), kTitle) << "a scene just opened is marked as changed";

  // In Coin's view mode, a plain drag turns the camera; with Ctrl held it moves the light:
  // from the middle of the 3D area, a quarter of its width to the right.
  const int x = view.x + view.width / 2, y = view.y + view.height / 2;
  viewer.drag(x, y, x + view.width / 4, y + view.height / 10, true);
  const Image after = viewer.steadyGrab(view);

  // The camera did not move: the background is where it was (all but a few pixels of the
  // dragger, which moved with the light and may cover some).
  const std::vector<bool> was = background(before), is = background(after);
  int moved = 0;
  for (std::size_t i = 0; i < was.size(); ++i) moved += was[i] != is[i] ? 1 : 0;
  EXPECT_LT(moved, int(was.size()) / 200) << "the background moved: the drag turned the camera";
  // The light did: the shading and the shadows on the floor and the wall changed.
  EXPECT_LT(test::shareWithin(after, before, 20), 0.97)
      << "the Ctrl+drag left the picture as it was";
  if (HasFailure()) {
    writePng(test::outputDir() + "/before.png", before);
    writePng(test::outputDir() + "/after.png", after);
  }

  // The scene changed: the title says so, and closing asks whether to save it instead of
  // quitting (closing that question cancels it: the viewer goes on).
  EXPECT_EQ(viewer.title(), "coloured_shadows.iv* - ivshadow viewer");
  viewer.close();
  EXPECT_TRUE(viewer.waitForOtherWindow("Save changes")) << viewer.output();
  EXPECT_TRUE(viewer.running()) << "the viewer quit without asking to save the changed scene";
}

TEST(ViewerWindow, TheWheelScrollsThePanelWithoutChangingAField) {
  // A small window, so that the panel's fields reach below its bottom and it scrolls.
  InteractiveViewer viewer(kScreen1024, {scene(), "--size", "480x300", "--no-light-dragger"},
                           test::outputDir() + "/config");
  ASSERT_TRUE(viewer.waitForWindow(kTitle));
  const test::WindowTree tree = viewer.settledTree();
  const ScreenRect view = InteractiveViewer::viewArea(tree);
  // The panel: the largest window right of the 3D area (the examiner's wheels lie between).
  ScreenRect panel;
  for (const ScreenRect& window : tree.all) {
    if (window.x >= view.x + view.width &&
        window.width * window.height > panel.width * panel.height)
      panel = window;
  }
  ASSERT_GT(panel.height, 100) << "no panel right of the 3D area";
  const Image before = viewer.steadyGrab(panel);
  // Down the panel's right half, where the spin boxes and combo boxes are, a few notches each:
  // under the pointer every moment is one field or another (maxLayers went from 6 to 1).
  for (int y = panel.y + 30; y < panel.y + panel.height - 10; y += 24) {
    viewer.wheelDown(panel.x + panel.width * 2 / 3, y, 2);
  }
  const Image after = viewer.steadyGrab(panel);
  EXPECT_LT(test::shareWithin(after, before, 0), 0.9) << "the panel did not scroll";
  EXPECT_EQ(viewer.title(), kTitle) << "the wheel changed a field of the scene";
  EXPECT_EQ(viewer.quit(), 0) << viewer.output();
}

}  // namespace
}  // namespace ivshadow
