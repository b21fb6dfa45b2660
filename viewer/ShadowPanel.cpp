#include "viewer/ShadowPanel.h"

#include "ivshadow/SoDeepShadowLight.h"
#include "ivshadow/SoPeelingSeparator.h"
#include "ivshadow/SoTransparentShadowGroup.h"
#include "nodes/NodesOfType.h"
#include "scene/FieldAssignment.h"
#include "scene/InputError.h"
#include "viewer/FieldEditor.h"

#include <Inventor/nodes/SoSeparator.h>

#include <QComboBox>
#include <QFontDatabase>
#include <QFormLayout>
#include <QLabel>
#include <QPushButton>
#include <QSignalBlocker>
#include <QStackedWidget>
#include <QVBoxLayout>

#include <set>

namespace ivshadow {
namespace {

struct FieldSpec {
  const char* name;
  FieldRange range;
};

// The fields the panel edits, per node type, with the ranges the nodes accept (wider values
// would only be clamped by the node with a warning, see nodes/DeepShadowSettings.cpp).
const std::vector<FieldSpec>& lightFields() {
  static const std::vector<FieldSpec> fields = {
      {"on", {}},
      {"intensity", {0.0, 1.0, 0.05, 2}},
      {"color", {0.0, 1.0, 0.05, 2}},
      {"location", {-1e5, 1e5, 0.1, 3}},
      {"method", {}},
      {"resolution", {1, 16384, 64, 0}},
      {"maxLayers", {1, 64, 1, 0}},
      {"shadowColor", {}},
      {"colorModel", {}},
      {"precision", {}},
      {"filter", {}},
      {"filterSize", {1, 9, 2, 0}},
      {"bias", {0.0, 100.0, 0.25, 2}},
      {"nearRadius", {-1.0, 1e6, 0.1, 3}},
      {"farRadius", {-1.0, 1e6, 0.1, 3}},
  };
  return fields;
}

const std::vector<FieldSpec>& groupFields() {
  static const std::vector<FieldSpec> fields = {{"isActive", {}}};
  return fields;
}

const std::vector<FieldSpec>& peelingFields() {
  static const std::vector<FieldSpec> fields = {
      {"method", {}},
      {"maxPasses", {0, SoPeelingSeparator::kMaxPasses, 1, 0}},
      {"earlyTermination", {}},
  };
  return fields;
}

const std::vector<FieldSpec>& fieldsOf(const SoNode* node) {
  if (node->isOfType(SoDeepShadowLight::getClassTypeId())) return lightFields();
  if (node->isOfType(SoPeelingSeparator::getClassTypeId())) return peelingFields();
  return groupFields();
}

std::string joined(const std::set<std::string>& names) {
  std::string out;
  for (const std::string& name : names) out += (out.empty() ? "" : ", ") + name;
  return out.empty() ? "(none)" : out;
}

}  // namespace

ShadowPanel::ShadowPanel(QWidget* parent) : QDockWidget("Deep shadows", parent) {
  setObjectName("ShadowPanel");
  auto* content = new QWidget(this);
  auto* layout = new QVBoxLayout(content);
  nodes_ = new QComboBox(content);
  nodes_->setToolTip("The deep shadow node whose fields are edited below");
  layout->addWidget(nodes_);
  forms_ = new QStackedWidget(content);
  layout->addWidget(forms_);

  emptyPage_ = new QWidget(forms_);
  auto* emptyLayout = new QVBoxLayout(emptyPage_);
  auto* explanation = new QLabel(
      "This scene has no deep shadow nodes. Adding a light puts the scene in a "
      "TransparentShadowGroup with a DeepShadowLight above it.",
      emptyPage_);
  explanation->setWordWrap(true);
  emptyLayout->addWidget(explanation);
  auto* add = new QPushButton("Add deep shadow light", emptyPage_);
  emptyLayout->addWidget(add);
  emptyLayout->addStretch();
  connect(add, &QPushButton::clicked, this, [this] {
    if (addLight_) addLight_();
  });
  forms_->addWidget(emptyPage_);

  figures_ = new QLabel(content);
  figures_->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
  figures_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  figures_->setAlignment(Qt::AlignLeft | Qt::AlignTop);
  layout->addWidget(figures_);
  layout->addStretch();
  setWidget(content);

  connect(nodes_, QOverload<int>::of(&QComboBox::currentIndexChanged), this, [this](int index) {
    // Page 0 is the "no deep shadow node" page; entry i is page i + 1.
    forms_->setCurrentIndex(index < 0 ? 0 : index + 1);
    if (selected_) selected_(selectedNode());
  });
  setScene(nullptr, {});
}

ShadowPanel::~ShadowPanel() {
  // The editors detach from their fields before the nodes they hold go.
  clear();
}

void ShadowPanel::clear() {
  const QSignalBlocker block(nodes_);
  nodes_->clear();
  while (forms_->count() > 1) {
    QWidget* page = forms_->widget(1);
    forms_->removeWidget(page);
    delete page;
  }
  entries_.clear();
}

void ShadowPanel::setScene(SoSeparator* root, const std::string& sceneName) {
  // After a reload the user goes on editing the node of the same name.
  const QString previous = nodes_->currentText();
  clear();
  sceneName_ = sceneName;
  // The list is filled silently: the selection is announced once, when it is complete.
  const QSignalBlocker block(nodes_);
  if (root != nullptr) {
    std::map<QString, int> unnamed;
    auto add = [&](SoNode& node) {
      // Named as in files: Coin registers the classes with or without the "So".
      QString type = node.getTypeId().getName().getString();
      if (type.startsWith("So")) type = type.mid(2);
      const QString name = node.getName().getString();
      addEntry(&node, name.isEmpty() ? QString("%1 %2").arg(type).arg(++unnamed[type])
                                     : QString("%1 (%2)").arg(name, type));
    };
    forEachNodeOfType<SoTransparentShadowGroup>(root, add);
    forEachNodeOfType<SoDeepShadowLight>(root, add);
    forEachNodeOfType<SoPeelingSeparator>(root, add);
  }
  nodes_->setEnabled(!entries_.empty());
  // Start on the first light: its fields are the ones most often changed.
  int first = 0;
  for (std::size_t i = 0; i < entries_.size(); ++i) {
    if (entries_[i].node->isOfType(SoDeepShadowLight::getClassTypeId())) {
      first = static_cast<int>(i);
      break;
    }
  }
  const int same = nodes_->findText(previous);
  if (!previous.isEmpty() && same >= 0) first = same;
  nodes_->setCurrentIndex(entries_.empty() ? -1 : first);
  forms_->setCurrentIndex(entries_.empty() ? 0 : first + 1);
  if (selected_) selected_(selectedNode());
}

void ShadowPanel::addEntry(SoNode* node, const QString& label) {
  Entry entry;
  entry.node = CoinRef<SoNode>(node);
  entry.name = node->getName().getString();
  auto* page = new QWidget(forms_);
  auto* form = new QFormLayout(page);
  for (const FieldSpec& spec : fieldsOf(node)) {
    SoField* field = node->getField(SbName(spec.name));
    if (field == nullptr || !FieldEditor::supports(field)) continue;
    auto* editor = new FieldEditor(field, spec.range, page);
    form->addRow(spec.name, editor);
    entry.editors[spec.name] = editor;
  }
  forms_->addWidget(page);
  nodes_->addItem(label);
  entries_.push_back(std::move(entry));
}

SoNode* ShadowPanel::selectedNode() const {
  const int index = nodes_->currentIndex();
  return index < 0 ? nullptr : entries_[static_cast<std::size_t>(index)].node.get();
}

void ShadowPanel::selectNode(SoNode* node) {
  for (std::size_t i = 0; i < entries_.size(); ++i) {
    if (entries_[i].node.get() == node) nodes_->setCurrentIndex(static_cast<int>(i));
  }
}

void ShadowPanel::assign(const FieldAssignment& assignment) {
  const std::string where = "--set '" + assignment.text + "': error: ";
  std::set<std::string> names;
  bool found = false;
  for (std::size_t i = 0; i < entries_.size(); ++i) {
    Entry& entry = entries_[i];
    if (!entry.name.empty()) names.insert(entry.name);
    if (entry.name != assignment.node) continue;
    found = true;
    const auto editor = entry.editors.find(assignment.field);
    if (editor == entry.editors.end()) {
      std::set<std::string> fields;
      for (const auto& known : entry.editors) fields.insert(known.first);
      throw InputError(where + "the shadow panel has no field '" + assignment.field + "' for '" +
                       assignment.node + "' (" + entry.node->getTypeId().getName().getString() +
                       "; its fields there: " + joined(fields) + ")");
    }
    // Shown as the user would see it: the edited node selected in the panel.
    nodes_->setCurrentIndex(static_cast<int>(i));
    const std::string problem = editor->second->setFromText(assignment.value);
    if (!problem.empty()) {
      throw InputError(where + "cannot set " + assignment.node + "." + assignment.field + " to '" +
                       assignment.value + "': " + problem);
    }
  }
  if (!found) {
    throw InputError(where + "no deep shadow node named '" + assignment.node + "' in " +
                     sceneName_ + " (the shadow panel's named nodes: " + joined(names) + ")");
  }
}

void ShadowPanel::setFigures(const QString& text) {
  figures_->setText(text);
}

}  // namespace ivshadow
