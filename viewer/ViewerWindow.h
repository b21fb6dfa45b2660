#pragma once

#include "scene/CoinRef.h"
#include "viewer/LightDragger.h"
#include "viewer/LiveFigures.h"
#include "viewer/RecentFiles.h"
#include "viewer/TimedExaminerViewer.h"

#include <QFileSystemWatcher>
#include <QMainWindow>
#include <QString>

#include <Inventor/SbMatrix.h>
#include <Inventor/SbVec3f.h>

#include <functional>

class QAction;
class QCloseEvent;
class QDragEnterEvent;
class QDropEvent;
class QLabel;
class QMimeData;
class QShowEvent;
class SbVec2f;
class SoDeepShadowLight;
class SoNode;
class SoSeparator;

namespace ivshadow {

class Image;
class MapInspector;
class OutputFiles;
class ShadowPanel;

// The viewer's main window: an examiner viewer with File ▸ Open, Open Recent, Reload, Save
// Scene As, Save Screenshot; .iv files dropped on the window open; the scene reloads when
// its file changes on disk. The deep shadow panel (a dock) edits the shadow nodes' fields
// live and shows the frame's figures; a dragger moves the selected deep shadow light; the
// map inspector (D) shows any face and layer of a light's deep shadow map.
class ViewerWindow : public QMainWindow {
 public:
  ViewerWindow();
  ~ViewerWindow() override;

  // Creates the examiner viewer; SoQt::init(this) must have run.
  void createViewer();

  // Reads and shows `path`. On failure keeps the current scene, reports the error (a dialog
  // when interactive) and returns the message; returns an empty string on success.
  std::string openScene(const QString& path);
  void reload();
  // Saves the next frame to `path`, in the format its name asks for; `done` gets an empty
  // string or the error.
  void saveScreenshot(const QString& path, std::function<void(const std::string&)> done);
  // Gives the next frame to `done`, for a scripted run that writes it with its other outputs.
  void captureScreenshot(std::function<void(const Image&)> done);
  // Writes the scene as loaded and edited (not the viewer's camera, headlight or dragger).
  // Returns an empty string or the error.
  std::string saveSceneAs(const QString& path);
  // Adds that scene to `outputs` as `path`; the window must live until they are committed.
  void addScene(OutputFiles& outputs, const std::string& path);
  // What the panel's Add shadows does: puts a scene without deep shadow nodes into a shadow
  // group in which its lights cast (a deep shadow light where it has none); with `ground`, a
  // ground under the model that catches the shadows too. The window keeps its width. Returns
  // an empty string or why it cannot.
  std::string addDeepShadowLight(bool ground = false);
  // Whether the scene changed in the window (fields, the light moved, shadows added) since it
  // was opened or saved; the title shows it, and closing asks to save it.
  bool sceneModified() const { return isWindowModified(); }
  void setSceneModified(bool modified);
  int framesDrawn() const;
  // Call once after show(): makes Mesa's software GLX take the window's final size before
  // the first frame (docs/KNOWN_ISSUES.md) and draws that frame.
  void settleDrawable();
  // Non-interactive (scripted) windows report errors on stderr and show no light dragger.
  void setInteractive(bool interactive);
  // Lays the window out around a 3D area of width x height: interactive windows are then
  // fitted to the screen (the 3D area shrinks, the panel keeps its width), scripted ones keep
  // exactly that area for their screenshots.
  void setViewerSize(int width, int height);
  // Interactive windows: the geometry and docks of the last window closed (Qt's settings),
  // fitted to the screen. False when there is nothing to restore.
  bool restoreLayout();
  // Interactive windows: folds the panel's sections that were folded when the last window
  // closed.
  void restoreFoldedSections();
  // Shrinks and moves the window so that it and its frame lie on the screen it is on.
  void fitToScreen();
  // Whether the camera moves back to bring the dragger into view when a scene opens or a
  // light is added: interactive windows, and scripted ones that ask to show the dragger.
  void setBringLightIntoView(bool on) { frameLight_ = on; }
  // Shows or hides the dragger on the selected deep shadow light (View ▸ Light Dragger).
  void setLightDraggerShown(bool shown);

  // Called after every frame drawn, with its wall time, once the figures are collected.
  void onFrameDrawn(std::function<void(double wallMs)> callback) {
    frameDrawnCallback_ = std::move(callback);
  }
  LightDragger& lightDragger() { return dragger_; }

  ShadowPanel& panel() { return *panel_; }
  MapInspector& inspector() { return *inspector_; }
  const LiveFigures& figures() const { return figures_; }

  // The local .iv or .wrl file a drag carries, or an empty string.
  static QString droppedScene(const QMimeData* data);

 protected:
  void dragEnterEvent(QDragEnterEvent* event) override;
  void dropEvent(QDropEvent* event) override;
  void showEvent(QShowEvent* event) override;
  void closeEvent(QCloseEvent* event) override;

 private:
  void buildMenus();
  // Lets the 3D area shrink to kSmallestView and fits the window to the screen.
  void shrinkableToFit();
  void chooseAndOpen();
  void chooseAndSaveScreenshot();
  void chooseAndSaveScene();
  void frameDrawn(double wallMs, double gpuMs);
  void nodeSelected(SoNode* node);
  void showDragger(bool show);
  // Moves the camera back (a perspective camera along its view, an orthographic one widens)
  // until the selected light's dragger lies inside the view: lights above a scene were outside
  // the picture, where their dragger could not be reached.
  void bringLightIntoView();
  // Ctrl+drag, or a drag in the Move Light mode: the light follows the pointer in the plane
  // through it that faces the camera.
  bool dragLight(TimedExaminerViewer::LightDrag phase, const SbVec2f& position);
  // Returns false when the user cancelled (or the file could not be written).
  bool chooseAndSaveSceneDone();
  SoDeepShadowLight* lightToMove() const;
  void showMessage(const QString& text);
  void reportError(const std::string& message);

  TimedExaminerViewer* viewer_ = nullptr;
  ShadowPanel* panel_ = nullptr;
  MapInspector* inspector_ = nullptr;
  QAction* draggerAction_ = nullptr;
  QAction* moveLightAction_ = nullptr;
  QLabel* frameLabel_ = nullptr;
  QFileSystemWatcher watcher_;
  RecentFiles recent_;
  LightDragger dragger_;
  LiveFigures figures_;
  QString path_;
  CoinRef<SoSeparator> scene_;
  bool interactive_ = true;
  bool frameLight_ = true;
  // The light being moved by a Ctrl+drag: where it and the pointer's plane point started.
  CoinRef<SoDeepShadowLight> movingLight_;
  SbMatrix movingToWorld_;
  SbVec3f movingStart_;
  SbVec3f pointerStart_;
  std::function<void(double)> frameDrawnCallback_;
};

}  // namespace ivshadow
