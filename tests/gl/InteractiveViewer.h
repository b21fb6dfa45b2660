#pragma once

#include "tests/gl/ScreenGrab.h"

#include <string>
#include <vector>

namespace ivshadow::test {

// The viewer started as a user starts it (no --screenshot: an interactive window with its
// examiner decorations, the panel, the window manager's frame) on screen `screen` of the
// suite's X server, kept running while the test looks at it. Settings live in `configDir`
// (XDG_CONFIG_HOME), so that two runs of one test can share them.
class InteractiveViewer {
 public:
  InteractiveViewer(int screen, const std::vector<std::string>& arguments,
                    const std::string& configDir);
  // Ends a viewer still running (SIGTERM), so that a failed test leaves no window behind.
  ~InteractiveViewer();
  InteractiveViewer(const InteractiveViewer&) = delete;
  InteractiveViewer& operator=(const InteractiveViewer&) = delete;

  // ":N.S", the viewer's screen.
  const std::string& display() const { return display_; }
  // Waits until the window titled `title` is mapped; false (and a test failure) when it does
  // not come or the viewer exits first.
  bool waitForWindow(const std::string& title);
  const std::string& windowId() const { return window_; }
  // Waits until the window's geometry has stopped changing (the window manager frames and
  // places it, the viewer fits itself to the screen after that) and returns its tree.
  WindowTree settledTree();
  // The 3D area: the largest window without windows below (the GL widget; the panel, menu
  // and status bars are the others).
  static ScreenRect viewArea(const WindowTree& tree);
  // Asks the window manager to resize the window's inside to width x height.
  void resize(int width, int height);
  // Closes the window as a user does (the window manager's close) and returns the viewer's
  // exit status.
  int quit();
  // Asks the window manager to close the window, and returns at once.
  void close();
  // The window's title now (the viewer marks a changed scene with "*").
  std::string title() const;
  // Waits until a window titled `title` (a regular expression, as xdotool takes it) shows on
  // the viewer's screen; false when none does, or the viewer exits first.
  bool waitForOtherWindow(const std::string& title);
  // Whether the viewer is still running.
  bool running();
  // Moves the pointer from (x0, y0) to (x1, y1) with the left button held (and Ctrl, when
  // `ctrl`), in steps, as a hand does. Screen coordinates.
  void drag(int x0, int y0, int x1, int y1, bool ctrl);
  // Turns the mouse wheel `clicks` notches down with the pointer at (x, y).
  void wheelDown(int x, int y, int clicks);
  // The pixels of `rect` once two grabs a moment apart agree (the viewer has stopped
  // drawing: a traced group's refined frame comes a quarter of a second after a motion).
  Image steadyGrab(const ScreenRect& rect);
  std::string output() const;

 private:
  // The visible window titled title_ ("" when there is none).
  std::string findWindow() const;

  int screen_ = 0;
  std::string display_;
  std::string out_;
  std::string err_;
  std::string title_;
  std::string window_;
  int pid_ = -1;
};

}  // namespace ivshadow::test
