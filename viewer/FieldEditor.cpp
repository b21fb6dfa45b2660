#include "viewer/FieldEditor.h"

#include "viewer/FocusedWheel.h"

#include <Inventor/fields/SoSFBool.h>
#include <Inventor/fields/SoSFColor.h>
#include <Inventor/fields/SoSFEnum.h>
#include <Inventor/fields/SoSFFloat.h>
#include <Inventor/fields/SoSFInt32.h>
#include <Inventor/fields/SoSFVec3f.h>

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFontMetrics>
#include <QHBoxLayout>
#include <QSignalBlocker>
#include <QSizePolicy>
#include <QSpinBox>
#include <QStringList>

#include <cmath>

namespace ivshadow {
namespace {

// Room for a spin box's arrows and frame beside its text.
constexpr int kSpinBoxButtonsWidth = 28;

bool isOfType(const SoField* field, SoType type) {
  return field->getTypeId().isDerivedFrom(type);
}

// Three components of an SoSFVec3f or SoSFColor.
std::vector<float> componentsOf(const SoField* field) {
  if (isOfType(field, SoSFColor::getClassTypeId())) {
    const SbColor& c = static_cast<const SoSFColor*>(field)->getValue();
    return {c[0], c[1], c[2]};
  }
  const SbVec3f& v = static_cast<const SoSFVec3f*>(field)->getValue();
  return {v[0], v[1], v[2]};
}

}  // namespace

FieldEditor::FieldEditor(SoField* field, const FieldRange& range, QWidget* parent)
    : QWidget(parent), field_(field), range_(range), sensor_(&FieldEditor::fieldChanged, this) {
  auto* layout = new QHBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  if (isOfType(field, SoSFBool::getClassTypeId())) {
    check_ = new QCheckBox(this);
    layout->addWidget(check_);
    connect(check_, &QCheckBox::toggled, this, [this] { writeField(); });
  } else if (isOfType(field, SoSFEnum::getClassTypeId())) {
    combo_ = new FocusedWheel<QComboBox>(this);
    const auto* enumField = static_cast<const SoSFEnum*>(field);
    for (int i = 0; i < enumField->getNumEnums(); ++i) {
      SbName name;
      const int value = enumField->getEnum(i, name);
      combo_->addItem(name.getString(), value);
    }
    layout->addWidget(combo_);
    connect(combo_, QOverload<int>::of(&QComboBox::currentIndexChanged), this,
            [this] { writeField(); });
  } else if (isOfType(field, SoSFInt32::getClassTypeId())) {
    integer_ = new FocusedWheel<QSpinBox>(this);
    integer_->setRange(static_cast<int>(range.minimum), static_cast<int>(range.maximum));
    integer_->setSingleStep(static_cast<int>(std::max(1.0, range.step)));
    // One write per finished edit rather than per typed digit: a resolution of 1, then 10,
    // then 102 on the way to 1024 would rebuild the map three times for nothing.
    integer_->setKeyboardTracking(false);
    layout->addWidget(integer_);
    connect(integer_, QOverload<int>::of(&QSpinBox::valueChanged), this, [this] { writeField(); });
  } else {
    const int count = isOfType(field, SoSFFloat::getClassTypeId()) ? 1 : 3;
    for (int i = 0; i < count; ++i) {
      reals_.push_back(makeDoubleSpinBox());
      layout->addWidget(reals_.back());
    }
  }
  refresh();
  sensor_.attach(field_);
}

FieldEditor::~FieldEditor() {
  sensor_.detach();
}

bool FieldEditor::supports(const SoField* field) {
  for (SoType type :
       {SoSFBool::getClassTypeId(), SoSFEnum::getClassTypeId(), SoSFInt32::getClassTypeId(),
        SoSFFloat::getClassTypeId(), SoSFVec3f::getClassTypeId(), SoSFColor::getClassTypeId()}) {
    if (isOfType(field, type)) return true;
  }
  return false;
}

QDoubleSpinBox* FieldEditor::makeDoubleSpinBox() {
  QDoubleSpinBox* box = new FocusedWheel<QDoubleSpinBox>(this);
  box->setRange(range_.minimum, range_.maximum);
  box->setSingleStep(range_.step);
  box->setDecimals(range_.decimals);
  box->setKeyboardTracking(false);
  // Sized for a value of a few digits rather than for the widest value in range (location
  // reaches 1e5), so that three of them side by side do not widen the panel.
  box->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Fixed);
  box->setMinimumWidth(box->fontMetrics().horizontalAdvance("-000.000") + kSpinBoxButtonsWidth);
  connect(box, QOverload<double>::of(&QDoubleSpinBox::valueChanged), this,
          [this] { writeField(); });
  return box;
}

void FieldEditor::fieldChanged(void* editor, SoSensor*) {
  static_cast<FieldEditor*>(editor)->refresh();
}

void FieldEditor::refresh() {
  // The widgets take the field's value without echoing it back into the field.
  if (check_) {
    const QSignalBlocker block(check_);
    check_->setChecked(static_cast<SoSFBool*>(field_)->getValue());
  } else if (combo_) {
    const QSignalBlocker block(combo_);
    combo_->setCurrentIndex(combo_->findData(static_cast<SoSFEnum*>(field_)->getValue()));
  } else if (integer_) {
    const QSignalBlocker block(integer_);
    integer_->setValue(static_cast<SoSFInt32*>(field_)->getValue());
  } else if (reals_.size() == 1) {
    const QSignalBlocker block(reals_[0]);
    reals_[0]->setValue(static_cast<SoSFFloat*>(field_)->getValue());
  } else {
    const std::vector<float> values = componentsOf(field_);
    for (std::size_t i = 0; i < reals_.size(); ++i) {
      const QSignalBlocker block(reals_[i]);
      reals_[i]->setValue(values[i]);
    }
  }
}

void FieldEditor::writeField() {
  if (check_) {
    static_cast<SoSFBool*>(field_)->setValue(check_->isChecked());
  } else if (combo_) {
    static_cast<SoSFEnum*>(field_)->setValue(combo_->currentData().toInt());
  } else if (integer_) {
    static_cast<SoSFInt32*>(field_)->setValue(integer_->value());
  } else if (reals_.size() == 1) {
    static_cast<SoSFFloat*>(field_)->setValue(static_cast<float>(reals_[0]->value()));
  } else {
    const float x = static_cast<float>(reals_[0]->value());
    const float y = static_cast<float>(reals_[1]->value());
    const float z = static_cast<float>(reals_[2]->value());
    if (isOfType(field_, SoSFColor::getClassTypeId())) {
      static_cast<SoSFColor*>(field_)->setValue(x, y, z);
    } else {
      static_cast<SoSFVec3f*>(field_)->setValue(x, y, z);
    }
  }
  if (edited_) edited_();
}

std::string FieldEditor::setFromText(const std::string& text) {
  const QString value = QString::fromStdString(text).trimmed();
  if (check_) {
    if (value != "TRUE" && value != "FALSE") return "expected TRUE or FALSE";
    const QSignalBlocker block(check_);
    check_->setChecked(value == "TRUE");
    writeField();
    return {};
  }
  if (combo_) {
    const int index = combo_->findText(value);
    if (index < 0) {
      QStringList names;
      for (int i = 0; i < combo_->count(); ++i) names << combo_->itemText(i);
      return "expected one of " + names.join(", ").toStdString();
    }
    const QSignalBlocker block(combo_);
    combo_->setCurrentIndex(index);
    writeField();
    return {};
  }
  const QStringList words = value.split(' ', Qt::SkipEmptyParts);
  const std::size_t count = integer_ ? 1 : reals_.size();
  const std::string expected =
      count == 1 ? (integer_ ? "an integer" : "a number") : "three numbers";
  const std::string inRange = " from " + QString::number(range_.minimum).toStdString() + " to " +
                              QString::number(range_.maximum).toStdString();
  if (words.size() != static_cast<int>(count)) return "expected " + expected + inRange;
  std::vector<double> numbers;
  for (const QString& word : words) {
    bool ok = false;
    const double number = integer_ ? word.toInt(&ok) : word.toDouble(&ok);
    if (!ok || !std::isfinite(number) || number < range_.minimum || number > range_.maximum) {
      return "expected " + expected + inRange;
    }
    numbers.push_back(number);
  }
  if (integer_) {
    const QSignalBlocker block(integer_);
    integer_->setValue(static_cast<int>(numbers[0]));
  } else {
    for (std::size_t i = 0; i < reals_.size(); ++i) {
      const QSignalBlocker block(reals_[i]);
      reals_[i]->setValue(numbers[i]);
    }
  }
  // Written once, by the same function the widgets' change signals call.
  writeField();
  return {};
}

}  // namespace ivshadow
