#include "viewer/CollapsibleSection.h"

#include <QFormLayout>
#include <QToolButton>
#include <QVBoxLayout>

namespace ivshadow {

CollapsibleSection::CollapsibleSection(const QString& title, QWidget* parent) : QWidget(parent) {
  setObjectName(title);
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->setSpacing(2);
  header_ = new QToolButton(this);
  header_->setText(title);
  header_->setCheckable(true);
  header_->setToolButtonStyle(Qt::ToolButtonTextBesideIcon);
  header_->setAutoRaise(true);
  header_->setStyleSheet("QToolButton { font-weight: bold; }");
  layout->addWidget(header_);
  body_ = new QWidget(this);
  form_ = new QFormLayout(body_);
  // Indented under the title, so the rows read as its contents.
  form_->setContentsMargins(16, 0, 0, 4);
  layout->addWidget(body_);
  setExpanded(true);
  // Only the user's clicks are reported; setExpanded is the program's own doing.
  connect(header_, &QToolButton::clicked, this, [this](bool on) {
    setExpanded(on);
    if (toggled_) toggled_(on);
  });
}

QString CollapsibleSection::title() const {
  return header_->text();
}

bool CollapsibleSection::expanded() const {
  return header_->isChecked();
}

void CollapsibleSection::setExpanded(bool expanded) {
  header_->setChecked(expanded);
  header_->setArrowType(expanded ? Qt::DownArrow : Qt::RightArrow);
  body_->setVisible(expanded);
}

}  // namespace ivshadow
