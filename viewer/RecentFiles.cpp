#include "viewer/RecentFiles.h"

#include <QFileInfo>
#include <QMenu>
#include <QSettings>

namespace ivshadow {
namespace {

const char* const kKey = "recentFiles";

}  // namespace

void RecentFiles::add(const QString& path) {
  const QString absolute = QFileInfo(path).absoluteFilePath();
  QStringList files = list();
  files.removeAll(absolute);
  files.prepend(absolute);
  while (files.size() > kMaximum) files.removeLast();
  QSettings store("ivshadow", "viewer");
  store.setValue(kKey, files);
}

QStringList RecentFiles::list() const {
  return QSettings("ivshadow", "viewer").value(kKey).toStringList();
}

void RecentFiles::attach(QMenu* menu, std::function<void(const QString&)> open) {
  QObject::connect(menu, &QMenu::aboutToShow, menu, [this, menu, open] {
    menu->clear();
    const QStringList files = list();
    for (int i = 0; i < files.size(); ++i) {
      // Numbered like other applications' recent lists: 1..8 pick them in the open menu.
      const QString label = QString("&%1 %2").arg(i + 1).arg(QFileInfo(files[i]).fileName());
      QAction* action = menu->addAction(label, menu, [open, file = files[i]] { open(file); });
      action->setToolTip(files[i]);
      action->setStatusTip(files[i]);
    }
    if (files.isEmpty()) menu->addAction("(none)")->setEnabled(false);
  });
}

}  // namespace ivshadow
