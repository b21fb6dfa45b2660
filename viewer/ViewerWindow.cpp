#include "viewer/ViewerWindow.h"

#include "image/AtomicFile.h"
#include "image/ImageFile.h"
#include "image/OutputFiles.h"
#include "ivshadow/SoDeepShadowLight.h"
#include "scene/InputError.h"
#include "scene/SceneLoader.h"
#include "scene/ViewSetup.h"
#include "viewer/MapInspector.h"
#include "viewer/SceneWriter.h"
#include "viewer/ShadowPanel.h"
#include "viewer/TimedExaminerViewer.h"
#include "viewer/WrapInShadowGroup.h"

#include <Inventor/nodes/SoCamera.h>
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

}  // namespace

ViewerWindow::ViewerWindow() {
  setWindowTitle("ivshadow viewer");
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
  panel_->onAddLightRequested([this] {
    const std::string error = addDeepShadowLight();
    if (!error.empty()) reportError(error);
  });
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
}

void ViewerWindow::setInteractive(bool interactive) {
  interactive_ = interactive;
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
    setWindowTitle(QFileInfo(path_).fileName() + " - ivshadow viewer");
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
  return {};
}

std::string ViewerWindow::addDeepShadowLight() {
  if (!scene_) return "ivshadow: error: no scene to add a deep shadow light to";
  dragger_.detach();
  SoNode* added =
      wrapInShadowGroup(scene_.get(), viewer_->getCamera(), viewer_->getViewportRegion());
  // The scene has a light of its own now; like `ivshadow render` of the saved file, the
  // viewer drops its headlight.
  viewer_->setHeadlight(!ViewSetup::hasActiveLight(scene_.get()));
  panel_->setScene(scene_.get(), path_.toStdString());
  panel_->selectNode(added);
  inspector_->setScene(scene_.get());
  showMessage(added->isOfType(SoDeepShadowLight::getClassTypeId())
                  ? "Added a shadow group and a deep shadow light; File > Save Scene As keeps them"
                  : "Added a shadow group: the scene's lights cast; File > Save Scene As keeps it");
  return {};
}

void ViewerWindow::settleDrawable() {
  // Push the final geometry to the X server, then swap once: Mesa's software GLX path reads
  // the drawable's size at the first make-current and again only after a swap.
  QApplication::processEvents();
  if (auto* gl = qobject_cast<QGLWidget*>(viewer_->getGLWidget())) {
    gl->makeCurrent();
    gl->swapBuffers();
  }
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
  figures_ = LiveFigures::collect(scene_.get(), wallMs, gpuMs, figures_);
  frameLabel_->setText(QString("frame %1 ms").arg(wallMs, 0, 'f', 1));
  panel_->setFigures(figures_.text());
  inspector_->frameDrawn(figures_.shadows.rebuilds);
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
  const QString path = QFileDialog::getSaveFileName(this, "Save scene as", QFileInfo(path_).path(),
                                                    "Open Inventor (*.iv);;All files (*)");
  if (path.isEmpty()) return;
  const std::string error = saveSceneAs(path);
  if (error.empty()) {
    showMessage("Saved " + path);
  } else {
    reportError(error);
  }
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
