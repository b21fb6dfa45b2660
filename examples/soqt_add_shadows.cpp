// An existing SoQt application — read a file, show it in an examiner viewer — that gains
// transparent, coloured shadows with the few lines marked "plugin": one init() call, the
// application's root wrapped in a SoTransparentShadowGroup with a SoDeepShadowLight, and the
// viewer's headlight turned off (docs/INTEGRATION.md, "Keep the shadows dark in a viewer").
// examples/python/soqt_add_shadows.py is the same in pivy.
// Usage: soqt_add_shadows SCENE.iv [--quit-after-ms N] [--screenshot FILE.png] [--headlight]
//   --quit-after-ms ends it after N ms; --screenshot then saves what the viewer's window shows
//   (read back from the X server); --headlight keeps the viewer's headlight on, to see what it
//   does to the shadows (tests/headlight/headlight_test.py compares the two).
#include <ivshadow/IvShadowInit.h>              // plugin
#include <ivshadow/SoDeepShadowLight.h>         // plugin
#include <ivshadow/SoTransparentShadowGroup.h>  // plugin

#include <Inventor/Qt/SoQt.h>
#include <Inventor/Qt/viewers/SoQtExaminerViewer.h>
#include <Inventor/SbBox3f.h>
#include <Inventor/SoDB.h>
#include <Inventor/SoInput.h>
#include <Inventor/actions/SoGetBoundingBoxAction.h>
#include <Inventor/nodes/SoCamera.h>
#include <Inventor/nodes/SoSeparator.h>

#include <QGuiApplication>
#include <QPixmap>
#include <QScreen>
#include <QTimer>
#include <QWidget>

#include <cstdio>
#include <cstdlib>
#include <string>

int main(int argc, char** argv) {
  const char* usage =
      "usage: soqt_add_shadows SCENE.iv [--quit-after-ms N] [--screenshot FILE.png] "
      "[--headlight]\n";
  if (argc < 2) {
    std::fprintf(stderr, "%s", usage);
    return 2;
  }
  int quitAfterMs = -1;
  std::string screenshot;
  bool headlight = false;
  for (int i = 2; i < argc; ++i) {
    const std::string option = argv[i];
    if (option == "--quit-after-ms" && i + 1 < argc) {
      quitAfterMs = std::atoi(argv[++i]);
    } else if (option == "--screenshot" && i + 1 < argc) {
      screenshot = argv[++i];
    } else if (option == "--headlight") {
      headlight = true;
    } else {
      std::fprintf(stderr, "%s", usage);
      return 2;
    }
  }
  QWidget* window = SoQt::init(argc, argv, argv[0]);
  ivshadow::init();  // plugin
  SoInput input;
  if (!input.openFile(argv[1])) return 2;
  SoSeparator* root = SoDB::readAll(&input);
  if (root == nullptr) return 2;

  // plugin: wrap the root; put a deep shadow light above the middle of the scene.
  auto* shadows = new SoTransparentShadowGroup;
  auto* light = new SoDeepShadowLight;
  SoGetBoundingBoxAction bounds(SbViewportRegion(640, 480));
  bounds.apply(root);
  const SbBox3f box = bounds.getBoundingBox();
  light->location.setValue(box.getCenter() +
                           SbVec3f(0.0f, 0.0f, 0.75f * (box.getMax()[2] - box.getMin()[2]) + 1.0f));
  shadows->addChild(root);
  // The light's location is in world coordinates only after the scene's camera: put before a
  // camera it would be in the camera's coordinates, and move with it.
  int camera = -1;
  for (int i = 0; i < root->getNumChildren() && camera < 0; ++i)
    if (root->getChild(i)->isOfType(SoCamera::getClassTypeId())) camera = i;
  if (camera >= 0)
    root->insertChild(light, camera + 1);
  else  // the viewer puts its own camera above the scene graph
    shadows->insertChild(light, 0);
  shadows->ref();

  auto* viewer = new SoQtExaminerViewer(window);
  viewer->setSceneGraph(shadows);
  // plugin: the viewer's headlight lies outside the group, so it lights without casting and
  // would wash the shadows out to mid-grey; the deep shadow light above lights the scene.
  viewer->setHeadlight(headlight ? TRUE : FALSE);
  viewer->show();
  SoQt::show(window);
  if (quitAfterMs >= 0)
    QTimer::singleShot(quitAfterMs, [viewer, screenshot] {
      if (!screenshot.empty()) {
        // A frame drawn now, at the window's size: the window manager may have resized the
        // window after the last one was drawn.
        viewer->render();
        QGuiApplication::primaryScreen()
            ->grabWindow(viewer->getGLWidget()->winId())
            .save(QString::fromStdString(screenshot));
      }
      SoQt::exitMainLoop();
    });
  SoQt::mainLoop();
  delete viewer;
  shadows->unref();
  return 0;
}
