#pragma once

#include <QString>
#include <QStringList>

#include <functional>

class QMenu;

namespace ivshadow {

// The scene files opened last, newest first, kept with QSettings (organisation "ivshadow",
// application "viewer": ~/.config/ivshadow/viewer.conf on Linux, key recentFiles) so that
// they survive the session. Feeds a File ▸ Open Recent menu.
class RecentFiles {
 public:
  static constexpr int kMaximum = 8;

  // Moves `path` (made absolute) to the front of the list.
  void add(const QString& path);
  QStringList list() const;
  // Refills `menu` with the list each time it is about to show; `open` gets the chosen path.
  void attach(QMenu* menu, std::function<void(const QString&)> open);
};

}  // namespace ivshadow
