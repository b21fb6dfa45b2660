#include "viewer/ViewerCommandLine.h"

#include <CLI/CLI.hpp>

namespace ivshadow {

void useProjectErrorFormat(CLI::App& app) {
  app.failure_message([](const CLI::App* failed, const CLI::Error& error) {
    std::string command = failed->get_name();
    for (const CLI::App* sub : failed->get_subcommands()) command += " " + sub->get_name();
    return failed->get_name() + ": error: " + error.what() + "\nRun \"" + command +
           " --help\" for the options.\n";
  });
}

void addViewerOptions(CLI::App& app, ViewerOptions& options) {
  app.add_option("scene", options.scene, "Open Inventor scene file (.iv)");
  app.add_option("--screenshot", options.screenshot,
                 "Save the second frame drawn to this PNG and quit");
  app.add_option("--size", options.size,
                 "3D area WIDTHxHEIGHT (default: as the window was last closed, else 800x600; "
                 "an interactive window is then fitted to the screen)");
  app.add_flag("--add-light", options.addLight,
               "Put a scene without deep shadow nodes into a shadow group in which its lights "
               "cast (a deep shadow light where it has none), as the panel's Add shadows does");
  app.add_flag("--add-ground", options.addGround,
               "With --add-light: also a ground under the model that catches its shadows (and "
               "a fill light where the scene had no light), as the panel's check box does");
  app.add_option("--set", options.assignments,
                 "NAME.field=VALUE: set a field of a deep shadow node through the shadow panel "
                 "(repeatable)")
      // One value per --set, so a scene file after it stays the positional argument.
      ->allow_extra_args(false);
  app.add_option("--save-scene", options.saveScene,
                 "Write the scene with its current field values to this .iv file and quit "
                 "(after --add-light and --set)");
  app.add_option("--figures", options.figures,
                 "With --screenshot: write the live figures of that frame to this JSON file");
  app.add_option("--window-shot", options.windowShot,
                 "With --screenshot: also save the whole window, panel included, to this PNG");
  app.add_flag("--light-dragger", options.lightDragger,
               "With --screenshot: show the light dragger, which scripted runs leave out");
  app.add_flag("--no-light-dragger", options.noLightDragger,
               "Start without the light dragger (View > Light Dragger shows it)");
  app.add_option("--drag-light", options.dragLight,
                 "With --screenshot: first drag the light dragger N steps, one per frame, "
                 "wait for the picture to settle, and add the drag's frame rate to --figures")
      ->check(CLI::Range(1, 100000));
  app.add_option("--inspect", options.inspect,
                 "LIGHT:FACE:LAYER[:visibility], e.g. Lamp:-z:1: open the map inspector on that "
                 "layer (depth unless :visibility); with --screenshot, print what it shows");
  app.add_option("--inspect-out", options.inspectOut,
                 "With --screenshot and --inspect: save the inspector's picture to this PNG");
}

}  // namespace ivshadow
