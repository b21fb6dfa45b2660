#include "viewer/ViewerWindow.h"

#include "image_files/AtomicFile.h"
#include "image_files/ImageFile.h"
#include "image_files/OutputFiles.h"
#include "ivshadow/SoDeepShadowLight.h"
#include "scene/InputError.h"
#include "scene_input/SceneLoader.h"
#include "scene_input/ViewSetup.h"
#include "viewer/MapInspector.h"
#include "viewer/SceneWriter.h"
#include "viewer/ShadowPanel.h"
#include "viewer/WrapInShadowGroup.h"

#include "ivshadow/SoTransparentShadowGroup.h"

#include <Inventor/SbLine.h>
#include <Inventor/SbPlane.h>
#include <Inventor/SbViewVolume.h>
#include <Inventor/nodes/SoCamera.h>
#include <Inventor/nodes/SoOrthographicCamera.h>
#include <Inventor/nodes/SoPerspectiveCamera.h>
#include <Inventor/nodes/SoSeparator.h>

#include <QAction>
#include <QApplication>
#include <QCloseEvent>
#include <QDragEnterEvent>
#include <QDropEvent>
#include <QFileDialog>
#include <QFileInfo>
#include <QGLWidget>
#include <QLabel>
#include <QLayout>
#include <QMenuBar>
#include <QMessageBox>
#include <QMimeData>
#include <QScreen>
#include <QSettings>
#include <QShortcut>
#include <QShowEvent>
#include <QStatusBar>
#include <QTimer>
#include <QUrl>

#include <algorithm>
#include <cmath>
#include <iostream>

namespace ivshadow {
namespace {

// Qt settings (~/.config/ivshadow/viewer.conf) of the window's layout.
const char* const kGeometryKey = "window/geometry";
const char* const kStateKey = "window/state";
const char* const kCollapsedKey = "window/collapsedSections";
// The 3D area never shrinks below this, however small the window is made.
const QSize kSmallestView(160, 120);
// A title bar and borders of the usual size, assumed before the window manager tells.
const QMargins kFrameAllowance(4, 28, 4, 4);
// Brought into view, the light's dragger lies within this share of the view's half-width and
// half-height from the centre.
constexpr float kLightInView = 0.85f;

// The view volume the examiner draws with: Coin's camera fitted to the viewport as
// SoCamera::viewportMapping ADJUST_CAMERA does (a viewport taller than wide widens the view).
SbViewVolume viewVolumeOf(SoCamera* camera, float aspect) {
  SbViewVolume volume = camera->getViewVolume(aspect);
  if (aspect < 1.0f) volume.scale(1.0f / aspect);
  return volume;
}

}  // namespace

ViewerWindow::ViewerWindow() {
  setWindowTitle("ivshadow viewer[*]");
  // saveState() names the docks by their object names.
  setObjectName("ViewerWindow");
  frameLabel_ = new QLabel(this);
  statusBar()->addPermanentWidget(frameLabel_);
  // Editors save by writing several times or by replacing the file; a short delay lets the
  // file settle before it is read again.
  connect(&watcher_, &QFileSystemWatcher::fileChanged, this,
          [this] { QTimer::singleShot(250, this, [this] { reload(); }); });
  panel_ = new ShadowPanel(this);
  addDockWidget(Qt::RightDockWidgetArea, panel_);
  panel_->onAddShadowsRequested([this](bool ground) {
    const std::string error = addDeepShadowLight(ground);
    if (!error.empty()) reportError(error);
  });
  panel_->onFieldEdited([this] { setSceneModified(true); });
  dragger_.onDragged([this] { setSceneModified(true); });
  panel_->onNodeSelected([this](SoNode* node) { nodeSelected(node); });
  inspector_ = new MapInspector(this);
  addDockWidget(Qt::RightDockWidgetArea, inspector_);
  inspector_->hide();
  // Asked for from inside a frame: the redraw is scheduled once that frame is finished.
  inspector_->onRedrawNeeded([this] {
    QTimer::singleShot(0, this, [this] {
      if (viewer_) viewer_->scheduleRedraw();
    });
  });
  setAcceptDrops(true);
  buildMenus();
}

ViewerWindow::~ViewerWindow() {
  dragger_.detach();
  inspector_->setScene(nullptr);
  delete viewer_;
}

void ViewerWindow::createViewer() {
  auto* area = new QWidget(this);
  setCentralWidget(area);
  viewer_ = new TimedExaminerViewer(area);
  viewer_->onFrameTimed([this](double wallMs, double gpuMs) { frameDrawn(wallMs, gpuMs); });
  viewer_->onLightDrag([this](TimedExaminerViewer::LightDrag phase, const SbVec2f& position) {
    return dragLight(phase, position);
  });
}

void ViewerWindow::buildMenus() {
  QMenu* file = menuBar()->addMenu("&File");
  file->addAction(
      "&Open...", this, [this] { chooseAndOpen(); }, QKeySequence::Open);
  recent_.attach(file->addMenu("Open &Recent"), [this](const QString& path) { openScene(path); });
  file->addAction(
      "&Reload", this, [this] { reload(); }, QKeySequence(Qt::Key_F5));
  file->addSeparator();
  file->addAction(
      "Save Scene &As...", this, [this] { chooseAndSaveScene(); },
      QKeySequence(Qt::CTRL | Qt::Key_S));
  file->addAction(
      "Save &Screenshot...", this, [this] { chooseAndSaveScreenshot(); },
      QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_S));
  file->addSeparator();
  file->addAction(
      "&Quit", this, [this] { close(); }, QKeySequence::Quit);

  QMenu* view = menuBar()->addMenu("&View");
  view->addAction(panel_->toggleViewAction());
  // The keys of seeds/000's demo: D shows the map, F1-F6 pick the face, 1-9 the layer.
  QAction* inspect = inspector_->toggleViewAction();
  inspect->setShortcut(QKeySequence(Qt::Key_D));
  view->addAction(inspect);
  for (int face = 0; face < 6; ++face) {
    auto* key = new QShortcut(QKeySequence(Qt::Key_F1 + face), this);
    connect(key, &QShortcut::activated, this, [this, face] { inspector_->selectFace(face); });
  }
  for (int layer = 1; layer <= 9; ++layer) {
    auto* key = new QShortcut(QKeySequence(Qt::Key_0 + layer), this);
    connect(key, &QShortcut::activated, this, [this, layer] { inspector_->selectLayer(layer); });
  }
  draggerAction_ = view->addAction("Light &Dragger");
  draggerAction_->setCheckable(true);
  draggerAction_->setChecked(true);
  connect(draggerAction_, &QAction::toggled, this, [this](bool on) { showDragger(on); });
  // Coin's examiner turns the camera on a drag in its view mode, and only its pick mode (the
  // arrow icon, or Esc) lets the dragger be grabbed. Ctrl+drag moves the light in view mode;
  // this mode makes every left-button drag do so.
  moveLightAction_ = view->addAction("&Move Light (Ctrl+Drag)");
  moveLightAction_->setCheckable(true);
  moveLightAction_->setShortcut(QKeySequence(Qt::Key_L));
  moveLightAction_->setToolTip(
      "Drag in the 3D view to move the selected deep shadow light (without this, hold Ctrl "
      "while dragging)");
  connect(moveLightAction_, &QAction::toggled, this, [this](bool on) {
    if (viewer_) viewer_->setMoveLightMode(on);
  });
  panel_->addToolAction(moveLightAction_);
}

void ViewerWindow::setInteractive(bool interactive) {
  interactive_ = interactive;
  frameLight_ = interactive;
  // Scripted screenshots show the scene only, as `ivshadow render` draws it.
  draggerAction_->setChecked(interactive);
}

void ViewerWindow::setLightDraggerShown(bool shown) {
  draggerAction_->setChecked(shown);
}

void ViewerWindow::setViewerSize(int width, int height) {
  if (interactive_) {
    // The window is laid out around a 3D area of the size asked for (the examiner's
    // thumbwheels and buttons take their share of it); the panel beside it is as wide as
    // its content. Then the window is made to fit the screen, and the 3D area shrinks with
    // it; the minimum only holds while the window takes its size.
    centralWidget()->setMinimumSize(width, height);
    layout()->activate();
    resize(sizeHint());
    shrinkableToFit();
  } else {
    // Screenshots are exactly width x height: no decorations, fixed 3D area.
    viewer_->setDecoration(FALSE);
    centralWidget()->setFixedSize(width, height);
    viewer_->setSize(SbVec2s(static_cast<short>(width), static_cast<short>(height)));
    adjustSize();
  }
}

void ViewerWindow::restoreFoldedSections() {
  panel_->setCollapsedSections(QSettings("ivshadow", "viewer").value(kCollapsedKey).toStringList());
}

bool ViewerWindow::restoreLayout() {
  const QSettings settings("ivshadow", "viewer");
  const QByteArray geometry = settings.value(kGeometryKey).toByteArray();
  if (geometry.isEmpty() || !restoreGeometry(geometry)) return false;
  restoreState(settings.value(kStateKey).toByteArray());
  shrinkableToFit();
  return true;
}

void ViewerWindow::shrinkableToFit() {
  centralWidget()->setMinimumSize(kSmallestView);
  // The layout gave the window the minimum size of the moment; activated anew, it lets the
  // window shrink to fit.
  layout()->invalidate();
  layout()->activate();
  fitToScreen();
}

void ViewerWindow::fitToScreen() {
  const QRect available = screen()->availableGeometry();
  // The window manager's frame is known once the window is shown; before that, room is left
  // for a title bar and borders of the usual size.
  const QMargins frame = isVisible() ? QMargins(geometry().left() - frameGeometry().left(),
                                                geometry().top() - frameGeometry().top(),
                                                frameGeometry().right() - geometry().right(),
                                                frameGeometry().bottom() - geometry().bottom())
                                     : kFrameAllowance;
  const QSize room = available.size().shrunkBy(frame);
  if (width() > room.width() || height() > room.height()) resize(size().boundedTo(room));
  // Moved so that the frame lies on the screen, should the window reach past an edge (a
  // top-level window's position is that of its frame).
  const QRect outer = isVisible() ? frameGeometry() : QRect(pos(), size().grownBy(frame));
  const QPoint shift(
      std::max(available.left() - outer.left(), std::min(0, available.right() - outer.right())),
      std::max(available.top() - outer.top(), std::min(0, available.bottom() - outer.bottom())));
  if (!shift.isNull()) move(pos() + shift);
}

void ViewerWindow::showEvent(QShowEvent* event) {
  QMainWindow::showEvent(event);
  if (!interactive_) return;
  // The window manager adds its frame after the window is mapped; once it has, the frame is
  // known and the window is made to fit again.
  QTimer::singleShot(250, this, [this] { fitToScreen(); });
}

void ViewerWindow::closeEvent(QCloseEvent* event) {
  if (interactive_ && isWindowModified()) {
    const auto answer = QMessageBox::question(
        this, "Save changes? - ivshadow viewer",
        "The scene has changed since it was opened (fields, the light, added shadows). Save it "
        "before closing?",
        QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel, QMessageBox::Save);
    if (answer == QMessageBox::Cancel ||
        (answer == QMessageBox::Save && !chooseAndSaveSceneDone())) {
      event->ignore();
      return;
    }
  }
  if (interactive_) {
    // Scripted runs leave the settings alone: their windows are of the size asked for.
    QSettings settings("ivshadow", "viewer");
    settings.setValue(kGeometryKey, saveGeometry());
    settings.setValue(kStateKey, saveState());
    settings.setValue(kCollapsedKey, panel_->collapsedSections());
  }
  QMainWindow::closeEvent(event);
}

std::string ViewerWindow::openScene(const QString& path) {
  try {
    LoadedScene loaded = loadScene(path.toStdString());
    const bool sameFile = path_ == path;
    // On reload of a scene without its own camera, keep where the user was looking.
    CoinRef<SoCamera> previousCamera;
    if (sameFile && viewer_->getCamera()) {
      previousCamera = CoinRef<SoCamera>(static_cast<SoCamera*>(viewer_->getCamera()->copy()));
    }
    dragger_.detach();
    inspector_->setScene(nullptr);
    viewer_->setSceneGraph(loaded.root.get());
    // As in `ivshadow render`: the headlight only for scenes without lights of their own, so
    // the viewer shows what a headless render of the file shows.
    viewer_->setHeadlight(!ViewSetup::hasActiveLight(loaded.root.get()));
    SoCamera* camera = viewer_->getCamera();
    if (previousCamera && camera && camera->getTypeId() == previousCamera->getTypeId()) {
      camera->copyFieldValues(previousCamera.get());
    }
    scene_ = loaded.root;
    if (!path_.isEmpty()) watcher_.removePath(path_);
    path_ = path;
    watcher_.addPath(path_);
    recent_.add(path_);
    panel_->setScene(scene_.get(), path_.toStdString());
    inspector_->setScene(scene_.get());
    setWindowTitle(QFileInfo(path_).fileName() + "[*] - ivshadow viewer");
    setSceneModified(false);
    if (!sameFile && isVisible()) bringLightIntoView();
    showMessage(loaded.warnings.empty() ? "Loaded " + path_
                                        : QString::fromStdString(loaded.warnings.front()));
    return {};
  } catch (const InputError& error) {
    reportError(error.what());
    return error.what();
  }
}

void ViewerWindow::reload() {
  if (path_.isEmpty()) return;
  // Files replaced by rename drop out of the watch list; openScene adds them back.
  if (!QFileInfo::exists(path_)) return;
  openScene(path_);
}

void ViewerWindow::saveScreenshot(const QString& path,
                                  std::function<void(const std::string&)> done) {
  try {
    AtomicFile::checkWritable(path.toStdString(), "the screenshot");
    imageFormatFor(path.toStdString());
  } catch (const InputError& error) {
    done(error.what());
    return;
  }
  viewer_->captureNextFrame([path, done](const Image& image) {
    try {
      writeImage(path.toStdString(), image);
      done({});
    } catch (const std::exception& error) {
      done(error.what());
    }
  });
}

void ViewerWindow::captureScreenshot(std::function<void(const Image&)> done) {
  viewer_->captureNextFrame(std::move(done));
}

void ViewerWindow::addScene(OutputFiles& outputs, const std::string& path) {
  outputs.add(path, [this, path](const std::string& file) {
    if (!scene_) throw InputError("ivshadow: error: no scene to save");
    const LightDragger::Hidden noDragger(dragger_);
    const MapInspector::Hidden noProbe(*inspector_);
    writeSceneTo(scene_.get(), file, path);
  });
}

std::string ViewerWindow::saveSceneAs(const QString& path) {
  if (!scene_) return "ivshadow: error: no scene to save";
  try {
    const LightDragger::Hidden noDragger(dragger_);
    const MapInspector::Hidden noProbe(*inspector_);
    writeScene(scene_.get(), path.toStdString());
  } catch (const InputError& error) {
    return error.what();
  }
  recent_.add(path);
  setSceneModified(false);
  return {};
}

std::string ViewerWindow::addDeepShadowLight(bool ground) {
  if (!scene_) return "ivshadow: error: no scene to add a deep shadow light to";
  dragger_.detach();
  const bool hadLight = ViewSetup::hasActiveLight(scene_.get());
  SoNode* added =
      wrapInShadowGroup(scene_.get(), viewer_->getCamera(), viewer_->getViewportRegion());
  if (ground) {
    SoTransparentShadowGroup* group = nullptr;
    for (int i = 0; i < scene_->getNumChildren() && group == nullptr; ++i) {
      if (scene_->getChild(i)->isOfType(SoTransparentShadowGroup::getClassTypeId()))
        group = static_cast<SoTransparentShadowGroup*>(scene_->getChild(i));
    }
    if (group != nullptr)
      addShadowGround(group, viewer_->getCamera(), viewer_->getViewportRegion(), !hadLight);
  }
  // The scene has a light of its own now; like `ivshadow render` of the saved file, the
  // viewer drops its headlight.
  viewer_->setHeadlight(!ViewSetup::hasActiveLight(scene_.get()));
  // The panel's pages for the new nodes are wider than the page that offered the button; the
  // 3D area gives up the width rather than the window growing (for good: it was saved so).
  const QSize before = size();
  panel_->setScene(scene_.get(), path_.toStdString());
  panel_->selectNode(added);
  if (isVisible()) {
    layout()->activate();
    if (width() > before.width()) resize(before);
    QTimer::singleShot(0, this, [this, before] {
      if (width() > before.width()) resize(before);
    });
    bringLightIntoView();
  }
  inspector_->setScene(scene_.get());
  setSceneModified(true);
  showMessage(added->isOfType(SoDeepShadowLight::getClassTypeId())
                  ? "Added shadows and a light (Save Scene As keeps them)"
                  : "Added shadows: the scene's lights cast (Save Scene As keeps them)");
  return {};
}

void ViewerWindow::setSceneModified(bool modified) {
  setWindowModified(modified);
}

SoDeepShadowLight* ViewerWindow::lightToMove() const {
  SoNode* node = panel_->selectedNode();
  if (node != nullptr && node->isOfType(SoDeepShadowLight::getClassTypeId()))
    return static_cast<SoDeepShadowLight*>(node);
  return dragger_.light();
}

bool ViewerWindow::dragLight(TimedExaminerViewer::LightDrag phase, const SbVec2f& position) {
  SoCamera* camera = viewer_->getCamera();
  if (phase == TimedExaminerViewer::LightDrag::Start) {
    movingLight_.reset();
    SoDeepShadowLight* light = lightToMove();
    if (light == nullptr || camera == nullptr ||
        !LightDragger::toWorld(scene_.get(), light, movingToWorld_)) {
      showMessage("No deep shadow light is selected in the panel to move");
      return false;
    }
    movingLight_ = CoinRef<SoDeepShadowLight>(light);
    movingToWorld_.multVecMatrix(light->location.getValue(), movingStart_);
  }
  if (!movingLight_ || camera == nullptr) return false;
  // The pointer's ray met with the plane through the light's start that faces the camera: the
  // light moves with the pointer, at the distance it had.
  const SbViewVolume volume =
      viewVolumeOf(camera, viewer_->getViewportRegion().getViewportAspectRatio());
  SbLine ray;
  volume.projectPointToLine(position, ray);
  SbVec3f pointer;
  if (!SbPlane(volume.getProjectionDirection(), movingStart_).intersect(ray, pointer)) {
    // A drag that ends off the plane still lets the light go.
    if (phase == TimedExaminerViewer::LightDrag::Finish) movingLight_.reset();
    return true;
  }
  if (phase == TimedExaminerViewer::LightDrag::Start) {
    pointerStart_ = pointer;
    showMessage("Moving the light " + QString(movingLight_->getName().getString()));
    return true;
  }
  SbVec3f location;
  movingToWorld_.inverse().multVecMatrix(movingStart_ + (pointer - pointerStart_), location);
  movingLight_->location.setValue(location);
  setSceneModified(true);
  if (phase == TimedExaminerViewer::LightDrag::Finish) movingLight_.reset();
  return true;
}

void ViewerWindow::bringLightIntoView() {
  SbVec3f light;
  SoCamera* camera = viewer_ ? viewer_->getCamera() : nullptr;
  if (!frameLight_ || camera == nullptr || !dragger_.worldLocation(light)) return;
  const float aspect = viewer_->getViewportRegion().getViewportAspectRatio();
  // The light in the camera's coordinates: x right, y up, looking down -z.
  SbVec3f local;
  camera->orientation.getValue().inverse().multVec(light - camera->position.getValue(), local);
  // The view's half-height per unit of distance (perspective) or in units (orthographic), as
  // ADJUST_CAMERA fits it to the viewport.
  const float widen = aspect < 1.0f ? 1.0f / aspect : 1.0f;
  const bool perspective = camera->isOfType(SoPerspectiveCamera::getClassTypeId());
  if (!perspective && !camera->isOfType(SoOrthographicCamera::getClassTypeId())) return;
  const float halfY =
      perspective
          ? std::tan(0.5f * static_cast<SoPerspectiveCamera*>(camera)->heightAngle.getValue()) *
                widen
          : 0.5f * static_cast<SoOrthographicCamera*>(camera)->height.getValue() * widen;
  const float depth = perspective ? -local[2] : 1.0f;
  // A dragger whose ball (about one of its sizes across each way) lies whole in the view is
  // left where it is: the camera moves only for one that cannot be grabbed.
  const float ball = dragger_.worldSize();
  if (-local[2] > ball && std::fabs(local[1]) + ball <= halfY * depth &&
      std::fabs(local[0]) + ball <= halfY * aspect * depth)
    return;
  // Its ball and arrows reach about two of its sizes from the light: those come into view.
  const float reach = 2.0f * ball;
  const float up = std::fabs(local[1]) + reach, side = std::fabs(local[0]) + reach;
  SbVec3f back;
  camera->orientation.getValue().multVec(SbVec3f(0.0f, 0.0f, 1.0f), back);
  if (perspective) {
    const float tanY = kLightInView * halfY;
    const float tanX = tanY * aspect;
    const float away = std::max({0.0f, up / tanY - depth, side / tanX - depth});
    if (away <= 0.0f) return;
    camera->position.setValue(camera->position.getValue() + back * away);
    camera->focalDistance.setValue(camera->focalDistance.getValue() + away);
  } else {
    auto* orthographic = static_cast<SoOrthographicCamera*>(camera);
    const float needed =
        std::max(up / (kLightInView * halfY), side / (kLightInView * halfY * aspect));
    if (needed > 1.0f) orthographic->height.setValue(orthographic->height.getValue() * needed);
    // Behind the camera, the light would be clipped: the camera steps back past it.
    if (local[2] > -reach)
      camera->position.setValue(camera->position.getValue() + back * (local[2] + 2.0f * reach));
  }
}

void ViewerWindow::settleDrawable() {
  // Push the final geometry to the X server, then swap once: Mesa's software GLX path reads
  // the drawable's size at the first make-current and again only after a swap.
  QApplication::processEvents();
  if (auto* gl = qobject_cast<QGLWidget*>(viewer_->getGLWidget())) {
    gl->makeCurrent();
    gl->swapBuffers();
  }
  // The window has its final size: the dragger can be fitted into the view it shows.
  bringLightIntoView();
  viewer_->scheduleRedraw();
}

int ViewerWindow::framesDrawn() const {
  return viewer_ ? viewer_->framesDrawn() : 0;
}

QString ViewerWindow::droppedScene(const QMimeData* data) {
  if (data == nullptr || !data->hasUrls()) return {};
  for (const QUrl& url : data->urls()) {
    if (!url.isLocalFile()) continue;
    const QString suffix = QFileInfo(url.toLocalFile()).suffix().toLower();
    if (suffix == "iv" || suffix == "wrl") return url.toLocalFile();
  }
  return {};
}

void ViewerWindow::dragEnterEvent(QDragEnterEvent* event) {
  if (!droppedScene(event->mimeData()).isEmpty()) event->acceptProposedAction();
}

void ViewerWindow::dropEvent(QDropEvent* event) {
  const QString path = droppedScene(event->mimeData());
  if (path.isEmpty()) return;
  event->acceptProposedAction();
  openScene(path);
}

void ViewerWindow::frameDrawn(double wallMs, double gpuMs) {
  figures_ = LiveFigures::collect(scene_.get(), wallMs, gpuMs, viewer_->framesPerSecond(),
                                  viewer_->softwareRenderer(), figures_);
  frameLabel_->setText(QString("%1 fps  frame %2 ms  %3")
                           .arg(figures_.framesPerSecond, 0, 'f', 1)
                           .arg(wallMs, 0, 'f', 1)
                           .arg(figures_.pathSummary()));
  panel_->setFigures(figures_.text());
  inspector_->frameDrawn(figures_.shadows.rebuilds, viewer_->softwareRenderer());
  if (frameDrawnCallback_) frameDrawnCallback_(wallMs);
}

void ViewerWindow::nodeSelected(SoNode* node) {
  if (node == nullptr || !node->isOfType(SoDeepShadowLight::getClassTypeId())) return;
  if (draggerAction_ != nullptr && draggerAction_->isChecked()) {
    dragger_.attach(scene_.get(), static_cast<SoDeepShadowLight*>(node));
  }
}

void ViewerWindow::showDragger(bool show) {
  if (!show) {
    dragger_.detach();
    return;
  }
  SoNode* node = panel_->selectedNode();
  if (scene_ && node != nullptr && node->isOfType(SoDeepShadowLight::getClassTypeId())) {
    dragger_.attach(scene_.get(), static_cast<SoDeepShadowLight*>(node));
  }
}

void ViewerWindow::chooseAndOpen() {
  const QString path = QFileDialog::getOpenFileName(this, "Open scene", QFileInfo(path_).path(),
                                                    "Open Inventor (*.iv *.wrl);;All files (*)");
  if (!path.isEmpty()) openScene(path);
}

void ViewerWindow::chooseAndSaveScene() {
  chooseAndSaveSceneDone();
}

bool ViewerWindow::chooseAndSaveSceneDone() {
  const QString path = QFileDialog::getSaveFileName(this, "Save scene as", QFileInfo(path_).path(),
                                                    "Open Inventor (*.iv);;All files (*)");
  if (path.isEmpty()) return false;
  const std::string error = saveSceneAs(path);
  if (error.empty()) {
    showMessage("Saved " + path);
    return true;
  }
  reportError(error);
  return false;
}

void ViewerWindow::chooseAndSaveScreenshot() {
  const QString path = QFileDialog::getSaveFileName(this, "Save screenshot", "screenshot.png",
                                                    "Images (*.png *.jpg *.jpeg)");
  if (path.isEmpty()) return;
  saveScreenshot(path, [this, path](const std::string& error) {
    if (error.empty()) {
      showMessage("Saved " + path);
    } else {
      reportError(error);
    }
  });
}

void ViewerWindow::showMessage(const QString& text) {
  statusBar()->showMessage(text, 10000);
}

void ViewerWindow::reportError(const std::string& message) {
  showMessage(QString::fromStdString(message));
  if (interactive_) {
    QMessageBox::warning(this, "ivshadow viewer", QString::fromStdString(message));
  } else {
    std::cerr << message << '\n';
  }
}

}  // namespace ivshadow
