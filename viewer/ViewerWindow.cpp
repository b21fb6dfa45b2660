#include "viewer/ViewerWindow.h"

#include "scene/ViewSetup.h"

#include "image/AtomicFile.h"
#include "image/PngFile.h"
#include "scene/InputError.h"
#include "scene/SceneLoader.h"
#include "viewer/TimedExaminerViewer.h"

#include <Inventor/nodes/SoCamera.h>
#include <Inventor/nodes/SoSeparator.h>

#include <QApplication>
#include <QFileDialog>
#include <QFileInfo>
#include <QGLWidget>
#include <QLabel>
#include <QMenuBar>
#include <QMessageBox>
#include <QStatusBar>
#include <QTimer>

#include <iostream>

namespace ivshadow {

ViewerWindow::ViewerWindow() {
  setWindowTitle("ivshadow viewer");
  frameLabel_ = new QLabel(this);
  statusBar()->addPermanentWidget(frameLabel_);
  // Editors save by writing several times or by replacing the file; a short delay lets the
  // file settle before it is read again.
  connect(&watcher_, &QFileSystemWatcher::fileChanged, this,
          [this] { QTimer::singleShot(250, this, [this] { reload(); }); });
  buildMenus();
}

ViewerWindow::~ViewerWindow() {
  delete viewer_;
}

void ViewerWindow::createViewer() {
  auto* area = new QWidget(this);
  setCentralWidget(area);
  viewer_ = new TimedExaminerViewer(area);
  viewer_->onFrameTimed(
      [this](double ms) { frameLabel_->setText(QString("frame %1 ms").arg(ms, 0, 'f', 1)); });
}

void ViewerWindow::buildMenus() {
  QMenu* file = menuBar()->addMenu("&File");
  file->addAction(
      "&Open...", this, [this] { chooseAndOpen(); }, QKeySequence::Open);
  file->addAction(
      "&Reload", this, [this] { reload(); }, QKeySequence(Qt::Key_F5));
  file->addAction(
      "Save &Screenshot...", this, [this] { chooseAndSaveScreenshot(); },
      QKeySequence(Qt::CTRL | Qt::SHIFT | Qt::Key_S));
  file->addSeparator();
  file->addAction(
      "&Quit", this, [this] { close(); }, QKeySequence::Quit);
}

void ViewerWindow::setViewerSize(int width, int height) {
  if (interactive_) {
    // The examiner's thumbwheels and buttons come on top of the 3D area; the window stays
    // resizable.
    viewer_->setSize(SbVec2s(static_cast<short>(width), static_cast<short>(height)));
    centralWidget()->resize(width, height);
    resize(sizeHint().expandedTo(QSize(width, height)));
  } else {
    // Screenshots are exactly width x height: no decorations, fixed 3D area.
    viewer_->setDecoration(FALSE);
    centralWidget()->setFixedSize(width, height);
    viewer_->setSize(SbVec2s(static_cast<short>(width), static_cast<short>(height)));
    adjustSize();
  }
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
  } catch (const InputError& error) {
    done(error.what());
    return;
  }
  viewer_->captureNextFrame([path, done](const Image& image) {
    try {
      writePng(path.toStdString(), image);
      done({});
    } catch (const std::exception& error) {
      done(error.what());
    }
  });
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

void ViewerWindow::chooseAndOpen() {
  const QString path = QFileDialog::getOpenFileName(this, "Open scene", QFileInfo(path_).path(),
                                                    "Open Inventor (*.iv *.wrl);;All files (*)");
  if (!path.isEmpty()) openScene(path);
}

void ViewerWindow::chooseAndSaveScreenshot() {
  const QString path =
      QFileDialog::getSaveFileName(this, "Save screenshot", "screenshot.png", "PNG (*.png)");
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
