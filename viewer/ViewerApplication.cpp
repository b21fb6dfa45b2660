#include "viewer/ViewerApplication.h"

#include "gl/ShaderConstants.h"
#include "headless/CoinOffscreenContexts.h"
#include "image_files/AtomicFile.h"
#include "image_files/CommandPaths.h"
#include "image_files/ImageFile.h"
#include "image_files/ImageSize.h"
#include "image_files/OutputFiles.h"
#include "ivshadow/DeepShadowStatistics.h"
#include "ivshadow/IvShadowInit.h"
#include "scene/InputError.h"
#include "scene_input/FieldAssignment.h"
#include "viewer/MapInspector.h"
#include "viewer/QtImage.h"
#include "viewer/ScriptedDrag.h"
#include "viewer/ShadowPanel.h"
#include "viewer/ViewerWindow.h"

#include <Inventor/Qt/SoQt.h>
#include <Inventor/nodes/SoSeparator.h>

#include <QApplication>
#include <QImage>
#include <QPixmap>
#include <QScreen>
#include <QStringList>
#include <QTimer>

#include <nlohmann/json.hpp>

#include <cstdlib>
#include <functional>
#include <iostream>
#include <memory>
#include <vector>

// Last: Xlib defines macros (None, Bool, Status) that Qt's headers also use.
#include <X11/Xlib.h>

namespace ivshadow {
namespace {

const char* const kDefaultSize = "800x600";

struct InspectRequest {
  QString light;
  int face = -1;
  int layer = 0;
  bool visibility = false;
};

// "LIGHT:FACE:LAYER[:visibility]", FACE one of +x -x +y -y +z -z, LAYER from 1.
InspectRequest parseInspect(const std::string& text) {
  const QStringList parts = QString::fromStdString(text).split(':');
  const QStringList faces = {"+x", "-x", "+y", "-y", "+z", "-z"};
  InspectRequest request;
  bool ok =
      parts.size() == 3 || (parts.size() == 4 && (parts[3] == "visibility" || parts[3] == "depth"));
  if (ok) {
    request.light = parts[0];
    request.face = faces.indexOf(parts[1]);
    request.layer = parts[2].toInt(&ok);
    request.visibility = parts.size() == 4 && parts[3] == "visibility";
  }
  if (!ok || request.light.isEmpty() || request.face < 0 || request.layer < 1 ||
      request.layer > kMaxMapLayers) {
    throw InputError("--inspect '" + text +
                     "': error: expected LIGHT:FACE:LAYER[:visibility|:depth] with FACE one of +x "
                     "-x +y -y +z -z and LAYER from 1 to " +
                     std::to_string(kMaxMapLayers) + ", e.g. Lamp:-z:1");
  }
  return request;
}

// Runs `body`; what it throws is printed: 2 for bad input (InputError), 1 for anything else.
int withViewerExitStatus(const std::function<void()>& body) {
  try {
    body();
    return 0;
  } catch (const InputError& error) {
    std::cerr << error.what() << '\n';
    return 2;
  } catch (const std::exception& error) {
    std::cerr << error.what() << '\n';
    return 1;
  }
}

// Everything a scripted run can get wrong in its options, found before any window opens or
// any file is written.
std::vector<FieldAssignment> checkScriptedOptions(const ViewerOptions& options) {
  if (options.scene.empty() &&
      (options.addLight || !options.assignments.empty() || !options.saveScene.empty())) {
    throw InputError("ivshadow: error: --add-light, --set and --save-scene need a scene file");
  }
  if ((!options.figures.empty() || !options.windowShot.empty() || !options.inspectOut.empty() ||
       options.dragLight > 0) &&
      options.screenshot.empty()) {
    throw InputError(
        "ivshadow: error: --figures, --window-shot, --inspect-out and --drag-light need "
        "--screenshot");
  }
  if (options.addGround && !options.addLight) {
    throw InputError("ivshadow: error: --add-ground needs --add-light");
  }
  if (!options.inspectOut.empty() && options.inspect.empty()) {
    throw InputError("ivshadow: error: --inspect-out needs --inspect");
  }
  if (!options.inspect.empty()) parseInspect(options.inspect);
  // --save-scene over the scene it read is refused too: a scripted edit in place would lose
  // the file's comments and `File` includes for good (the window's Save Scene As dialog asks
  // before it replaces a file).
  CommandPaths()
      .input("scene", options.scene)
      .output("--screenshot", options.screenshot)
      .output("--save-scene", options.saveScene)
      .output("--figures", options.figures)
      .output("--window-shot", options.windowShot)
      .output("--inspect-out", options.inspectOut)
      .check();
  // Every picture follows its name's format, as `ivshadow render` does (a .jpg screenshot
  // was PNG data under that name).
  for (const std::string* picture : {&options.screenshot, &options.windowShot, &options.inspectOut})
    if (!picture->empty()) imageFormatFor(*picture);
  if (!options.screenshot.empty()) AtomicFile::checkWritable(options.screenshot, "the screenshot");
  if (!options.saveScene.empty()) AtomicFile::checkWritable(options.saveScene, "the scene");
  if (!options.figures.empty()) AtomicFile::checkWritable(options.figures, "the figures");
  if (!options.windowShot.empty()) AtomicFile::checkWritable(options.windowShot, "the window");
  if (!options.inspectOut.empty()) {
    AtomicFile::checkWritable(options.inspectOut, "the inspector's picture");
  }
  std::vector<FieldAssignment> assignments;
  for (const std::string& text : options.assignments) {
    assignments.push_back(FieldAssignment::parse(text));
  }
  return assignments;
}

// SoQt draws through GLX, so it needs an X display; without one (none set, or one that cannot
// be reached) Qt would abort. 0 when the viewer can reach one, else 3, said.
int checkDisplay() {
  const char* display = std::getenv("DISPLAY");
  if (display == nullptr || *display == '\0') {
    std::cerr << "ivshadow: error: the viewer needs an X display (DISPLAY is not set); use "
                 "'ivshadow render' to render without one\n";
    return 3;
  }
  if (Display* connection = XOpenDisplay(display)) {
    XCloseDisplay(connection);
    return 0;
  }
  std::cerr << "ivshadow: error: the viewer cannot open the X display '" << display
            << "' (DISPLAY); start an X server or use 'ivshadow render' to render without one\n";
  return 3;
}

// SoQt, the plugin's nodes and Coin's settings, as the viewer draws with them.
void initCoin(ViewerWindow& window) {
  SoQt::init(&window);
  init();
  // NURBS shapes give the casters' SoCallbackAction triangles only through an offscreen GL
  // context, which Coin's GLX code cannot make under Mesa's software GLX.
  installCoinOffscreenContexts();
  // Coin's render caches draw a scene's delayed transparent shapes wrongly lit by a point
  // light once a cache has been built (from about the third unchanged frame): the viewer's
  // frames then differed from the first frame, which `ivshadow render` draws, by up to 40
  // steps on every transparent shape (docs/KNOWN_ISSUES.md). Without caches every frame is
  // drawn as the first; Coin keeps its vertex buffers, so large shapes stay on the GPU.
  SoSeparator::setNumRenderCaches(0);
  // The live figures show each pass's GPU time.
  setPassTiming(true);
}

void showLightDragger(ViewerWindow& window, const ViewerOptions& options) {
  if (options.lightDragger || options.dragLight > 0) window.setLightDraggerShown(true);
  // A screenshot that asks for the dragger shows it as a window does, in view; --drag-light
  // keeps the file's camera, which its pictures are compared with.
  if (options.lightDragger && options.dragLight == 0) window.setBringLightIntoView(true);
  if (options.noLightDragger) window.setLightDraggerShown(false);
}

// Opens the scene and makes the scripted edits, through what the user would click: the
// panel's button and editors. 2 when a scripted run cannot go on, else 0.
int openAndEdit(ViewerWindow& window, const ViewerOptions& options,
                const std::vector<FieldAssignment>& assignments) {
  const bool scripted = options.scripted();
  if (!options.scene.empty()) {
    const std::string error = window.openScene(QString::fromStdString(options.scene));
    if (scripted && !error.empty()) return 2;
  }
  try {
    if (options.addLight) {
      const std::string error = window.addDeepShadowLight(options.addGround);
      if (!error.empty()) throw InputError(error);
    }
    for (const FieldAssignment& assignment : assignments) window.panel().assign(assignment);
  } catch (const InputError& error) {
    std::cerr << error.what() << '\n';
    if (scripted) return 2;
  }
  return 0;
}

// --save-scene without a screenshot, written once everything else has succeeded, so that a
// failed run leaves no file.
int saveScene(ViewerWindow& window, const ViewerOptions& options) {
  if (options.saveScene.empty()) return 0;
  const std::string error = window.saveSceneAs(QString::fromStdString(options.saveScene));
  if (!error.empty()) {
    std::cerr << error << '\n';
    return 2;
  }
  std::cout << "wrote " << options.saveScene << '\n';
  return 0;
}

void showInspector(ViewerWindow& window, const std::string& inspect) {
  const InspectRequest request = parseInspect(inspect);
  MapInspector& inspector = window.inspector();
  inspector.selectFace(request.face);
  inspector.selectLayer(request.layer);
  inspector.setShowVisibility(request.visibility);
  inspector.selectLight(request.light);
  inspector.show();
}

// Laid out once the panel holds the scene's nodes, which set its width. An interactive window
// without --size opens as the last one was closed.
void layOut(ViewerWindow& window, const ViewerOptions& options, const ImageSize& size) {
  const bool scripted = options.scripted();
  if (!scripted) window.restoreFoldedSections();
  if (scripted || !options.size.empty() || !window.restoreLayout()) {
    window.setViewerSize(size.width, size.height);
  }
  window.show();
  window.settleDrawable();
}

// What a scripted run's frames leave for its outputs: 0 once the screenshot is taken.
struct ScriptedCapture {
  int status = 1;
  Image screenshot;
  std::unique_ptr<ScriptedDrag> drag;  // --drag-light
  bool dragged = false;
};

// Runs the event loop until the screenshot is taken (after the drag, and once the inspector
// is up to date), or the run fails.
void captureScripted(ViewerWindow& window, const ViewerOptions& options, bool inspecting,
                     ScriptedCapture& capture) {
  // The screenshot is a frame drawn after the first one: should the first still go to a
  // drawable of a stale size (docs/KNOWN_ISSUES.md), the next is right.
  auto* waitForFirstFrame = new QTimer(&window);
  // --drag-light: the drag runs after the first frame, the screenshot after the drag.
  capture.dragged = options.dragLight == 0;
  QObject::connect(waitForFirstFrame, &QTimer::timeout, &window, [&, waitForFirstFrame] {
    if (window.framesDrawn() < 1) return;
    if (!capture.dragged) {
      if (!capture.drag) {
        capture.drag = std::make_unique<ScriptedDrag>(
            window, options.dragLight, [&, waitForFirstFrame](const std::string& error) {
              capture.dragged = true;
              if (error.empty()) return;
              waitForFirstFrame->stop();
              std::cerr << "ivshadow: error: " << error << '\n';
              capture.status = 2;
              QTimer::singleShot(0, qApp, [] { qApp->quit(); });
            });
        capture.drag->start();
      }
      return;
    }
    // The inspector reads the map during a frame after the one that built it.
    if (inspecting && !window.inspector().upToDate()) return;
    if (inspecting && window.inspector().picture().isNull()) {
      // A light or layer that is not there: bad input, and no output files.
      waitForFirstFrame->stop();
      std::cerr << "ivshadow: error: --inspect '" << options.inspect
                << "': " << window.inspector().status().toStdString() << '\n';
      capture.status = 2;
      qApp->quit();
      return;
    }
    waitForFirstFrame->stop();
    window.captureScreenshot([&capture](const Image& image) {
      capture.screenshot = image;
      capture.status = 0;
      // Quit after the frame is complete, so its figures are known.
      QTimer::singleShot(0, qApp, [] { qApp->quit(); });
    });
  });
  waitForFirstFrame->start(100);
  // A window that never draws (a broken GLX) must not hang scripts and tests.
  QTimer::singleShot(120000, qApp, [] {
    std::cerr << "ivshadow: error: the viewer drew no frame within 120 s\n";
    qApp->quit();
  });
  QApplication::exec();
}

// Every output together or none (image_files/OutputFiles): a figures file that cannot be written
// takes the screenshot with it.
int writeScriptedOutputs(ViewerWindow& window, const ViewerOptions& options, bool inspecting,
                         const ScriptedCapture& capture) {
  return withViewerExitStatus([&] {
    OutputFiles outputs;
    outputs.addImage(options.screenshot, capture.screenshot);
    Image inspectorPicture;
    if (inspecting && !options.inspectOut.empty()) {
      inspectorPicture = imageFromQt(window.inspector().picture());
      outputs.addImage(options.inspectOut, inspectorPicture);
    }
    if (!options.saveScene.empty()) window.addScene(outputs, options.saveScene);
    if (!options.figures.empty()) {
      nlohmann::json figures = nlohmann::json::parse(window.figures().json());
      if (capture.drag) figures["drag"] = nlohmann::json::parse(capture.drag->json());
      outputs.addText(options.figures, figures.dump() + "\n");
    }
    Image windowPicture;
    if (!options.windowShot.empty()) {
      // Read back from the X server: the GL area as last swapped, and the widgets around it.
      windowPicture = imageFromQt(window.screen()->grabWindow(window.winId()).toImage());
      outputs.addImage(options.windowShot, windowPicture);
    }
    outputs.commitWhole();
  });
}

// A scripted run with a screenshot: its frames, then its outputs.
int runScripted(ViewerWindow& window, const ViewerOptions& options, bool inspecting) {
  ScriptedCapture capture;
  captureScripted(window, options, inspecting, capture);
  if (capture.status != 0) return capture.status;
  const int status = writeScriptedOutputs(window, options, inspecting, capture);
  if (status != 0) return status;
  if (inspecting) std::cout << "inspector: " << window.inspector().status().toStdString() << '\n';
  for (const std::string* written : {&options.screenshot, &options.inspectOut, &options.saveScene,
                                     &options.figures, &options.windowShot})
    if (!written->empty()) std::cout << "wrote " << *written << '\n';
  return status;
}

}  // namespace

int runViewer(const ViewerOptions& options, const char* programName) {
  ImageSize size;
  std::vector<FieldAssignment> assignments;
  try {
    size = ImageSize::parse(options.size.empty() ? kDefaultSize : options.size, "--size");
    assignments = checkScriptedOptions(options);
  } catch (const InputError& error) {
    std::cerr << error.what() << '\n';
    return 2;
  }
  if (const int status = checkDisplay(); status != 0) return status;

  int argc = 1;
  char* argv[] = {const_cast<char*>(programName), nullptr};
  QApplication application(argc, argv);
  ViewerWindow window;
  initCoin(window);
  window.createViewer();
  const bool scripted = options.scripted();
  window.setInteractive(!scripted);
  showLightDragger(window, options);
  if (const int status = openAndEdit(window, options, assignments); status != 0) return status;
  if (scripted && options.screenshot.empty()) return saveScene(window, options);

  const bool inspecting = !options.inspect.empty();
  if (inspecting) showInspector(window, options.inspect);
  layOut(window, options, size);
  if (scripted) return runScripted(window, options, inspecting);
  return application.exec();
}

}  // namespace ivshadow
