#pragma once

#include "scene/CoinRef.h"

#include <QFileSystemWatcher>
#include <QMainWindow>
#include <QString>

#include <functional>

class QLabel;
class SoSeparator;

namespace ivshadow {

class TimedExaminerViewer;

// The viewer's main window: an examiner viewer with File ▸ Open, Reload, Save Screenshot,
// reload when the file changes on disk, and a status line with the frame time.
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
  // Saves the next frame to `path`; `done` gets an empty string or the error.
  void saveScreenshot(const QString& path, std::function<void(const std::string&)> done);
  int framesDrawn() const;
  // Call once after show(): makes Mesa's software GLX take the window's final size before
  // the first frame (docs/KNOWN_ISSUES.md) and draws that frame.
  void settleDrawable();
  void setInteractive(bool interactive) { interactive_ = interactive; }
  void setViewerSize(int width, int height);

 private:
  void buildMenus();
  void chooseAndOpen();
  void chooseAndSaveScreenshot();
  void showMessage(const QString& text);
  void reportError(const std::string& message);

  TimedExaminerViewer* viewer_ = nullptr;
  QLabel* frameLabel_ = nullptr;
  QFileSystemWatcher watcher_;
  QString path_;
  CoinRef<SoSeparator> scene_;
  bool interactive_ = true;
};

}  // namespace ivshadow
