// An existing SoQt application — read a file, show it in an examiner viewer — that gains
// transparent, coloured shadows with the few lines marked "plugin": one init() call, the
// application's root wrapped in a SoTransparentShadowGroup with a SoDeepShadowLight, and the
// viewer's headlight turned off.
// Usage: soqt_add_shadows SCENE.iv [--quit-after-ms N]
#include <ivshadow/IvShadowInit.h>              // plugin
#include <ivshadow/SoDeepShadowLight.h>         // plugin
#include <ivshadow/SoTransparentShadowGroup.h>  // plugin

#include <Inventor/Qt/SoQt.h>
#include <Inventor/Qt/viewers/SoQtExaminerViewer.h>
#include <Inventor/SbBox3f.h>
#include <Inventor/SoDB.h>
#include <Inventor/SoInput.h>
#include <Inventor/actions/SoGetBoundingBoxAction.h>
#include <Inventor/nodes/SoSeparator.h>

#include <QTimer>

#include <cstdio>
#include <cstdlib>
#include <string>

int main(int argc, char** argv) {
  if (argc < 2) {
    std::fprintf(stderr, "usage: soqt_add_shadows SCENE.iv [--quit-after-ms N]\n");
    return 2;
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
  shadows->addChild(light);
  shadows->addChild(root);
  shadows->ref();

  auto* viewer = new SoQtExaminerViewer(window);
  viewer->setSceneGraph(shadows);
  // plugin: the viewer's headlight lies outside the group, so it lights without casting and
  // would wash the shadows out to mid-grey; the deep shadow light above lights the scene.
  viewer->setHeadlight(FALSE);
  viewer->show();
  SoQt::show(window);
  if (argc == 4 && std::string(argv[2]) == "--quit-after-ms")
    QTimer::singleShot(std::atoi(argv[3]), [] { SoQt::exitMainLoop(); });
  SoQt::mainLoop();
  delete viewer;
  shadows->unref();
  return 0;
}
