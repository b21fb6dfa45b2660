#pragma once

#include <QString>
#include <QWidget>

#include <functional>

class QFormLayout;
class QToolButton;

namespace ivshadow {

// A titled part of the shadow panel that folds away under its title (an arrow button), so
// that the panel shows only the groups of fields the user works with. Holds a form of rows.
class CollapsibleSection : public QWidget {
 public:
  CollapsibleSection(const QString& title, QWidget* parent);

  QFormLayout* form() const { return form_; }
  QString title() const;
  bool expanded() const;
  void setExpanded(bool expanded);
  // Called with the new state when the user folds or unfolds the section.
  void onToggled(std::function<void(bool)> callback) { toggled_ = std::move(callback); }

 private:
  QToolButton* header_ = nullptr;
  QWidget* body_ = nullptr;
  QFormLayout* form_ = nullptr;
  std::function<void(bool)> toggled_;
};

}  // namespace ivshadow
