#include "tests/gl/InteractiveViewer.h"

#include "tests/gl/ViewerTestSupport.h"
#include "tests/support/TestSupport.h"

#include <gtest/gtest.h>

#include <sys/wait.h>
#include <algorithm>
#include <csignal>
#include <thread>

namespace ivshadow::test {
namespace {

// How long to wait for the window and its layout before giving up, in polls of kPoll: far
// beyond what a loaded machine needs (a few seconds), short of CTest's timeout.
constexpr int kPolls = 240;
constexpr std::chrono::milliseconds kPoll(250);

}  // namespace

InteractiveViewer::InteractiveViewer(int screen, const std::vector<std::string>& arguments,
                                     const std::string& configDir)
    : screen_(screen),
      display_(testDisplay() + "." + std::to_string(screen)),
      out_(outputDir() + "/viewer.out"),
      err_(outputDir() + "/viewer.err") {
  if (testDisplay().empty()) {
    ADD_FAILURE() << "no test X server: run the viewer tests through ctest (fixture xserver)";
    return;
  }
  std::vector<std::string> command = {viewerExe()};
  command.insert(command.end(), arguments.begin(), arguments.end());
  pid_ = startProcess(command, {"DISPLAY=" + display_, "XDG_CONFIG_HOME=" + configDir}, out_, err_);
  if (pid_ < 0) ADD_FAILURE() << "could not start " << viewerExe();
}

InteractiveViewer::~InteractiveViewer() {
  if (pid_ <= 0) return;
  ::kill(pid_, SIGTERM);
  waitForProcess(pid_);
}

std::string InteractiveViewer::findWindow() const {
  // Only this screen: xdotool searches every screen of the server by default, and the scripted
  // viewers of other tests, on screen 0, show the same scene under the same title (the
  // reopened "window" was once one of theirs, 707 x 471, and closing it quit nothing).
  const ProcessResult search = run(
      {"xdotool", "search", "--screen", std::to_string(screen_), "--onlyvisible", "--name", title_},
      {"DISPLAY=" + display_});
  const std::vector<std::string> found = lines(search.out);
  return found.empty() ? std::string() : found.front();
}

bool InteractiveViewer::waitForWindow(const std::string& title) {
  title_ = title;
  for (int i = 0; i < kPolls && pid_ > 0; ++i) {
    window_ = findWindow();
    if (!window_.empty()) return true;
    int status = 0;
    if (waitpid(pid_, &status, WNOHANG) == pid_) {
      pid_ = -1;
      ADD_FAILURE() << "the viewer exited before its window showed: " << output();
      return false;
    }
    std::this_thread::sleep_for(kPoll);
  }
  ADD_FAILURE() << "no window '" << title << "' on " << display_ << ": " << output();
  return false;
}

WindowTree InteractiveViewer::settledTree() {
  WindowTree previous = windowTree(display_, window_);
  int unchanged = 0;
  for (int i = 0; i < kPolls; ++i) {
    std::this_thread::sleep_for(kPoll);
    // Looked up each time: under load the first window found by its title was once gone a
    // moment later (xwininfo could not read it), another with the same title in its place.
    const std::string id = findWindow();
    if (id.empty()) continue;
    if (id != window_) unchanged = 0;
    window_ = id;
    WindowTree tree = windowTree(display_, window_);
    // Laid out for the window's present size: the widgets reach its right and bottom edges
    // (the status bar, the panel), and none lies outside. The window manager changes the
    // window first, the viewer follows when its event loop gets to it, between frames.
    bool right = false, bottom = false, inside = true;
    for (const ScreenRect& child : tree.all) {
      right = right || child.x + child.width == tree.window.x + tree.window.width;
      bottom = bottom || child.y + child.height == tree.window.y + tree.window.height;
      inside = inside && tree.window.contains(child);
    }
    const bool same = tree.window == previous.window && tree.all == previous.all;
    unchanged = same && right && bottom && inside ? unchanged + 1 : 0;
    // Unchanged over three polls, framed: the window manager and the viewer are done.
    if (unchanged >= 3 && frameExtents(display_, window_)[2] > 0) return tree;
    previous = tree;
  }
  ADD_FAILURE() << "the window's geometry did not settle";
  return previous;
}

ScreenRect InteractiveViewer::viewArea(const WindowTree& tree) {
  ScreenRect largest;
  for (const ScreenRect& leaf : tree.leaves) {
    if (leaf.width * leaf.height > largest.width * largest.height) largest = leaf;
  }
  return largest;
}

void InteractiveViewer::resize(int width, int height) {
  run({"xdotool", "windowsize", "--sync", window_, std::to_string(width), std::to_string(height)},
      {"DISPLAY=" + display_});
}

int InteractiveViewer::quit() {
  // Closed through the window manager (_NET_CLOSE_WINDOW, which sends the window
  // WM_DELETE_WINDOW), as by its close button. Not by a key: X has one keyboard focus for all
  // screens, and a scripted viewer of another test opening meanwhile took it, and the key.
  run({"wmctrl", "-i", "-c", window_}, {"DISPLAY=" + display_});
  for (int i = 0; i < kPolls; ++i) {
    int status = 0;
    if (waitpid(pid_, &status, WNOHANG) == pid_) {
      pid_ = -1;
      return WIFEXITED(status) ? WEXITSTATUS(status) : 128 + WTERMSIG(status);
    }
    std::this_thread::sleep_for(kPoll);
  }
  ADD_FAILURE() << "the viewer did not quit when its window was closed";
  return -1;
}

void InteractiveViewer::close() {
  run({"wmctrl", "-i", "-c", window_}, {"DISPLAY=" + display_});
}

std::string InteractiveViewer::title() const {
  const ProcessResult name = run({"xdotool", "getwindowname", window_}, {"DISPLAY=" + display_});
  const std::vector<std::string> found = lines(name.out);
  return found.empty() ? std::string() : found.front();
}

bool InteractiveViewer::waitForOtherWindow(const std::string& title) {
  for (int i = 0; i < kPolls && running(); ++i) {
    const ProcessResult search = run({"xdotool", "search", "--screen", std::to_string(screen_),
                                      "--onlyvisible", "--name", title},
                                     {"DISPLAY=" + display_});
    if (!lines(search.out).empty()) return true;
    std::this_thread::sleep_for(kPoll);
  }
  return false;
}

bool InteractiveViewer::running() {
  if (pid_ <= 0) return false;
  int status = 0;
  if (waitpid(pid_, &status, WNOHANG) == pid_) pid_ = -1;
  return pid_ > 0;
}

void InteractiveViewer::drag(int x0, int y0, int x1, int y1, bool ctrl) {
  // xdotool's XTEST events: the server's modifier state goes with the button events to the
  // window under the pointer, whichever window has the keyboard focus.
  std::vector<std::string> command = {
      "xdotool",          "mousemove",        "--screen", std::to_string(screen_),
      std::to_string(x0), std::to_string(y0), "sleep",    "0.2"};
  if (ctrl) command.insert(command.end(), {"keydown", "ctrl", "sleep", "0.1"});
  command.insert(command.end(), {"mousedown", "1", "sleep", "0.2"});
  constexpr int kSteps = 8;
  for (int step = 1; step <= kSteps; ++step) {
    command.insert(command.end(), {"mousemove", "--screen", std::to_string(screen_),
                                   std::to_string(x0 + (x1 - x0) * step / kSteps),
                                   std::to_string(y0 + (y1 - y0) * step / kSteps), "sleep", "0.1"});
  }
  command.insert(command.end(), {"mouseup", "1", "sleep", "0.1"});
  if (ctrl) command.insert(command.end(), {"keyup", "ctrl"});
  run(command, {"DISPLAY=" + display_});
}

void InteractiveViewer::wheelDown(int x, int y, int clicks) {
  std::vector<std::string> command = {
      "xdotool",         "mousemove",       "--screen", std::to_string(screen_),
      std::to_string(x), std::to_string(y), "sleep",    "0.1"};
  // Button 5: the wheel turned towards the user, which scrolls down.
  for (int i = 0; i < clicks; ++i) command.insert(command.end(), {"click", "5", "sleep", "0.1"});
  run(command, {"DISPLAY=" + display_});
}

Image InteractiveViewer::steadyGrab(const ScreenRect& rect) {
  Image previous = crop(grabScreen(display_), rect);
  for (int i = 0; i < kPolls; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(500));
    Image now = crop(grabScreen(display_), rect);
    if (now.width() == previous.width() && now.height() == previous.height() &&
        std::equal(now.data(),
                   now.data() + std::size_t(now.width()) * std::size_t(now.height()) * 4u,
                   previous.data()))
      return now;
    previous = std::move(now);
  }
  ADD_FAILURE() << "the screen kept changing";
  return previous;
}

std::string InteractiveViewer::output() const {
  return readText(out_) + readText(err_);
}

}  // namespace ivshadow::test
