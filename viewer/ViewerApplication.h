#pragma once

#include <string>
#include <vector>

namespace ivshadow {

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

// Runs the SoQt viewer until its window closes. Returns the process exit status: 0; 2 for bad
// input (scene, size, --set, output paths) in a scripted run; 3 when there is no display to
// open a window on; 1 when a screenshot could not be saved.
int runViewer(const ViewerOptions& options, const char* programName);

}  // namespace ivshadow
