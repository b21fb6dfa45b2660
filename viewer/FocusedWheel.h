#pragma once

#include <QWheelEvent>
#include <QWidget>

namespace ivshadow {

// A spin box or combo box that the mouse wheel changes only once it has the focus (a click or
// Tab): scrolling the panel over it otherwise changed the value under the pointer (maxLayers
// went from 6 to 1). Without the focus the wheel event is ignored, so it goes on to the panel's
// scroll area, which scrolls.
template <class Widget>
class FocusedWheel : public Widget {
 public:
  explicit FocusedWheel(QWidget* parent) : Widget(parent) { this->setFocusPolicy(Qt::StrongFocus); }

 protected:
  void wheelEvent(QWheelEvent* event) override {
    if (this->hasFocus()) {
      Widget::wheelEvent(event);
    } else {
      event->ignore();
    }
  }
};

}  // namespace ivshadow
