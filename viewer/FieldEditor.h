#pragma once

#include <Inventor/sensors/SoFieldSensor.h>

#include <QString>
#include <QWidget>

#include <functional>
#include <vector>

class QAbstractSpinBox;
class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QSpinBox;
class SoField;

namespace ivshadow {

// The range a panel offers for a numeric field (for vectors and colours, each component).
struct FieldRange {
  double minimum = 0.0;
  double maximum = 1.0;
  double step = 0.1;
  int decimals = 2;
};

// A widget bound to one field of a node: SoSFBool (check box), SoSFEnum (combo box of the
// enum's names), SoSFInt32 and SoSFFloat (spin boxes), SoSFVec3f and SoSFColor (three spin
// boxes). Every change the user makes is written to the field at once, so the scene redraws
// live; changes made to the field elsewhere (a dragger, another editor) show in the widget.
class FieldEditor : public QWidget {
 public:
  FieldEditor(SoField* field, const FieldRange& range, QWidget* parent);
  ~FieldEditor() override;

  static bool supports(const SoField* field);

  // Puts `text` (Inventor syntax: TRUE, an enum name, a number, "x y z") into the widget as
  // if the user had entered it, which writes it to the field. Returns an error message (what
  // was expected) for text that does not parse or lies outside the panel's range, or "".
  std::string setFromText(const std::string& text);
  // Called after each value the editor writes to the field (not for changes made elsewhere).
  void onEdited(std::function<void()> callback) { edited_ = std::move(callback); }

 private:
  static void fieldChanged(void* editor, SoSensor*);
  void refresh();
  void writeField();
  QDoubleSpinBox* makeDoubleSpinBox();

  SoField* field_;
  FieldRange range_;
  SoFieldSensor sensor_;
  QCheckBox* check_ = nullptr;
  QComboBox* combo_ = nullptr;
  QSpinBox* integer_ = nullptr;
  std::vector<QDoubleSpinBox*> reals_;
  std::function<void()> edited_;
};

}  // namespace ivshadow
