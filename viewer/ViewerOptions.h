#pragma once

#include <string>
#include <vector>

namespace ivshadow {

// What the viewer's command line asks for; `ivshadow-viewer` and `ivshadow view` parse the same
// options (viewer/ViewerCommandLine.h), without Qt.
struct ViewerOptions {
  std::string scene;       // may be empty: start with nothing loaded
  std::string screenshot;  // non-empty: save the second rendered frame here and quit
  std::string size;        // WIDTHxHEIGHT of the 3D area; empty: the last window's, else 800x600
  bool addLight = false;   // wrap the scene in a deep shadow group first
  bool addGround = false;  // with addLight: and add a ground that catches the shadows
  std::vector<std::string> assignments;  // NAME.field=VALUE, applied through the panel
  std::string saveScene;                 // non-empty: write the scene here and quit
  std::string figures;                   // non-empty: the screenshot frame's figures (JSON)
  std::string windowShot;       // non-empty: with --screenshot, the whole window, panel included
  bool lightDragger = false;    // scripted runs: show the light dragger all the same
  bool noLightDragger = false;  // interactive runs: start with the light dragger off
  std::string inspect;          // LIGHT:FACE:LAYER[:visibility], shown in the map inspector
  std::string inspectOut;       // non-empty: with --inspect, the inspector's picture (PNG)
  int dragLight = 0;            // with --screenshot: drag the light this many steps first

  // Scripted runs do their work and quit; errors go to stderr rather than dialogs.
  bool scripted() const { return !screenshot.empty() || !saveScene.empty(); }
};

}  // namespace ivshadow
