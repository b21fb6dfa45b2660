#include "viewer/ShadowPanel.h"

#include "ivshadow/SoDeepShadowDirectionalLight.h"
#include "ivshadow/SoDeepShadowLight.h"
#include "ivshadow/SoDeepShadowSpotLight.h"
#include "ivshadow/SoPeelingSeparator.h"
#include "ivshadow/SoTransparentShadowGroup.h"
#include "nodes/DeepShadowSettings.h"
#include "nodes/NodesOfType.h"
#include "nodes/ShadowFieldTable.h"
#include "scene/InputError.h"
#include "scene_input/FieldAssignment.h"
#include "viewer/CollapsibleSection.h"
#include "viewer/FieldEditor.h"
#include "viewer/FocusedWheel.h"

#include <Inventor/nodes/SoSeparator.h>

#include <QCheckBox>
#include <QComboBox>
#include <QFontDatabase>
#include <QFormLayout>
#include <QFrame>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QScrollArea>
#include <QScrollBar>
#include <QSignalBlocker>
#include <QSizePolicy>
#include <QStackedWidget>
#include <QToolButton>
#include <QVBoxLayout>

#include <set>

namespace ivshadow {
namespace {

// The panel's sections, in the order they appear; a node's page shows those it has fields
// in. "Rays" explains that the traced method has no settings of its own.
const char* const kLight = "Light";
const char* const kMethod = "Shadow method";
const char* const kMap = "Map";
const char* const kRays = "Rays";
const char* const kPeeling = "Peeling";
const char* const kFigures = "Figures";
const char* const kBounce = "Bounce";

struct FieldSpec {
  const char* section;
  const char* name;
  FieldRange range;
};

// The shadow fields the panel shows under the method and under Map, in its order.
constexpr ShadowFieldId kMethodFields[] = {ShadowFieldId::method, ShadowFieldId::shadowColor,
                                           ShadowFieldId::colorModel, ShadowFieldId::nearRadius,
                                           ShadowFieldId::farRadius};
constexpr ShadowFieldId kMapFields[] = {ShadowFieldId::resolution,    ShadowFieldId::maxLayers,
                                        ShadowFieldId::layerOverflow, ShadowFieldId::slices,
                                        ShadowFieldId::precision,     ShadowFieldId::filter,
                                        ShadowFieldId::filterSize,    ShadowFieldId::bias};

// A shadow field with the range of the fields' table (nodes/ShadowFieldTable.h): what the
// nodes accept, wider values would only be clamped by the node with a warning.
FieldSpec panelField(const char* section, ShadowFieldId id) {
  const ShadowFieldSpec& field = shadowField(id);
  if (field.kind == ShadowFieldKind::Enum) return {section, field.name, {}};
  return {section, field.name, {field.low.value, field.high.value, field.step, field.decimals}};
}

// The fields the panel edits, per node type, grouped as SoDeepShadowLight.h describes them:
// what applies to both methods under the method, what only the map uses under Map.
const std::vector<FieldSpec>& lightFields() {
  static const std::vector<FieldSpec> fields = [] {
    std::vector<FieldSpec> all = {
        {kLight, "on", {}},
        {kLight, "intensity", {0.0, 1.0, 0.05, 2}},
        {kLight, "color", {0.0, 1.0, 0.05, 2}},
        {kLight, "location", {-1e5, 1e5, 0.1, 3}},
        {kLight, "direction", {-1.0, 1.0, 0.05, 2}},
        {kLight, "cutOffAngle", {0.0, 1.5708, 0.05, 3}},
        {kLight, "dropOffRate", {0.0, 1.0, 0.05, 2}},
    };
    for (const ShadowFieldId id : kMethodFields) all.push_back(panelField(kMethod, id));
    for (const ShadowFieldId id : kMapFields) all.push_back(panelField(kMap, id));
    return all;
  }();
  return fields;
}

// `first`, then the specs of lightFields() that `type`'s nodes have a field for: the lights'
// kinds, and the group's shadow fields for its ordinary lights, share the specs of the fields
// of the same names.
std::vector<FieldSpec> fieldsOfType(SoType type, std::vector<FieldSpec> first) {
  auto* probe = static_cast<SoNode*>(type.createInstance());
  probe->ref();
  for (const FieldSpec& spec : lightFields())
    if (probe->getField(spec.name) != nullptr) first.push_back(spec);
  probe->unref();
  return first;
}

// The group's own fields, its lights' shadow fields, then its one bounce (bounceMapSize, a
// power of two, is left to the file: a spin box would offer the values between).
const std::vector<FieldSpec>& groupFields() {
  static const std::vector<FieldSpec> fields = [] {
    std::vector<FieldSpec> all =
        fieldsOfType(SoTransparentShadowGroup::getClassTypeId(),
                     {{kMethod, "isActive", {}},
                      {kMethod, "renderer", {}},
                      {kMethod, "movingResolution", {kMinMovingResolution, 1.0, 0.125, 3}},
                      {kMethod, "transparency", {}},
                      {kMethod, "castingLights", {}}});
    all.push_back({kBounce, "bounce", {}});
    all.push_back({kBounce, "bounceLights", {1, kMaxBounceLights, 16, 0}});
    return all;
  }();
  return fields;
}

const std::vector<FieldSpec>& peelingFields() {
  static const std::vector<FieldSpec> fields = {
      {kPeeling, "method", {}},
      {kPeeling, "maxPasses", {0, SoPeelingSeparator::kMaxPasses, 1, 0}},
      {kPeeling, "earlyTermination", {}},
  };
  return fields;
}

const std::vector<FieldSpec>& fieldsOf(const SoNode* node) {
  static const std::vector<FieldSpec> point = fieldsOfType(SoDeepShadowLight::getClassTypeId(), {});
  static const std::vector<FieldSpec> spot =
      fieldsOfType(SoDeepShadowSpotLight::getClassTypeId(), {});
  static const std::vector<FieldSpec> directional =
      fieldsOfType(SoDeepShadowDirectionalLight::getClassTypeId(), {});
  if (node->isOfType(SoDeepShadowLight::getClassTypeId())) return point;
  if (node->isOfType(SoDeepShadowSpotLight::getClassTypeId())) return spot;
  if (node->isOfType(SoDeepShadowDirectionalLight::getClassTypeId())) return directional;
  if (node->isOfType(SoPeelingSeparator::getClassTypeId())) return peelingFields();
  return groupFields();
}

// A label that wraps to the panel's width instead of setting it (Qt sizes a wrapping label
// for some 80 characters).
QLabel* wrappingLabel(const QString& text, QWidget* parent) {
  auto* label = new QLabel(text, parent);
  label->setWordWrap(true);
  QSizePolicy policy(QSizePolicy::Ignored, QSizePolicy::Preferred);
  policy.setHeightForWidth(true);
  label->setSizePolicy(policy);
  return label;
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
  nodes_ = new FocusedWheel<QComboBox>(content);
  nodes_->setToolTip("The deep shadow node whose fields are edited below");
  // Long node names are shortened rather than widening the panel.
  nodes_->setSizeAdjustPolicy(QComboBox::AdjustToMinimumContentsLengthWithIcon);
  nodes_->setMinimumContentsLength(16);
  layout->addWidget(nodes_);
  tools_ = new QHBoxLayout;
  layout->addLayout(tools_);

  // First, under the node list: what the frame cost is what is watched while editing, and was
  // below every section (four lines showed on a 1000-pixel-high screen).
  CollapsibleSection* figures = addSection(kFigures, content);
  layout->addWidget(figures);
  figures_ = new QLabel(figures);
  figures_->setFont(QFontDatabase::systemFont(QFontDatabase::FixedFont));
  figures_->setTextInteractionFlags(Qt::TextSelectableByMouse);
  figures_->setAlignment(Qt::AlignLeft | Qt::AlignTop);
  // The lines are short; one that is not is cut at the panel's edge rather than widening it.
  figures_->setSizePolicy(QSizePolicy::Ignored, QSizePolicy::Preferred);
  figures->form()->addRow(figures_);

  forms_ = new QStackedWidget(content);
  layout->addWidget(forms_);

  emptyPage_ = new QWidget(forms_);
  auto* emptyLayout = new QVBoxLayout(emptyPage_);
  emptyLayout->setContentsMargins(0, 0, 0, 0);
  auto* explanation = wrappingLabel(
      "This scene has no deep shadow nodes. Add shadows puts the scene in a "
      "TransparentShadowGroup, in which its own lights cast; a scene without lights gets one "
      "DeepShadowLight. A model without a floor casts its shadows into the void: the ground "
      "catches them.",
      emptyPage_);
  emptyLayout->addWidget(explanation);
  ground_ = new QCheckBox("with a ground under the model", emptyPage_);
  ground_->setChecked(true);
  ground_->setToolTip(
      "Adds a square below the model's bounding box that catches its shadows, and a fill light "
      "when the scene had no light of its own");
  emptyLayout->addWidget(ground_);
  auto* add = new QPushButton("Add shadows", emptyPage_);
  emptyLayout->addWidget(add);
  connect(add, &QPushButton::clicked, this, [this] {
    if (addShadows_) addShadows_(ground_->isChecked());
  });
  forms_->addWidget(emptyPage_);
  layout->addStretch();

  // Scrolls rather than growing taller than the window; as wide as its widest row.
  auto* scroll = new QScrollArea(this);
  scroll->setWidget(content);
  scroll->setWidgetResizable(true);
  scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAsNeeded);
  scroll->setFrameShape(QFrame::NoFrame);
  setWidget(scroll);

  connect(nodes_, QOverload<int>::of(&QComboBox::currentIndexChanged), this, [this](int index) {
    // Page 0 is the "no deep shadow node" page; entry i is page i + 1.
    forms_->setCurrentIndex(index < 0 ? 0 : index + 1);
    if (selected_) selected_(selectedNode());
  });
  setScene(nullptr, {});
}

int ShadowPanel::contentWidth() const {
  // The scroll area offers only its content's size hint, in which the spin boxes that may
  // shrink count for nothing; their minimum counts here, and the scroll bar beside them.
  const auto* scroll = static_cast<const QScrollArea*>(widget());
  QWidget* content = scroll->widget();
  // Pages just added reach the content's layout only with the next event loop pass; asked
  // now, it would still answer for the pages it had (Qt caches each widget's sizes).
  forms_->updateGeometry();
  content->layout()->invalidate();
  return content->sizeHint().expandedTo(content->minimumSizeHint()).width() +
         scroll->verticalScrollBar()->sizeHint().width();
}

CollapsibleSection* ShadowPanel::addSection(const QString& title, QWidget* parent) {
  auto* section = new CollapsibleSection(title, parent);
  section->setExpanded(!collapsed_.contains(title));
  section->onToggled([this, title](bool expanded) {
    if (expanded) {
      collapsed_.removeAll(title);
    } else if (!collapsed_.contains(title)) {
      collapsed_.append(title);
    }
    // The same section on the other nodes' pages folds with it.
    for (CollapsibleSection* other : sections()) {
      if (other->title() == title) other->setExpanded(expanded);
    }
  });
  return section;
}

std::vector<CollapsibleSection*> ShadowPanel::sections() const {
  // The classes have no Q_OBJECT (no moc), so findChildren<CollapsibleSection*> would match
  // every widget; the C++ type decides.
  std::vector<CollapsibleSection*> found;
  for (QWidget* child : findChildren<QWidget*>()) {
    if (auto* section = dynamic_cast<CollapsibleSection*>(child)) found.push_back(section);
  }
  return found;
}

QStringList ShadowPanel::collapsedSections() const {
  return collapsed_;
}

void ShadowPanel::setCollapsedSections(const QStringList& titles) {
  collapsed_ = titles;
  for (CollapsibleSection* section : sections()) {
    section->setExpanded(!collapsed_.contains(section->title()));
  }
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
    forEachNodeOfType<SoDeepShadowSpotLight>(root, add);
    forEachNodeOfType<SoDeepShadowDirectionalLight>(root, add);
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
  // As wide as the widest page, so that switching nodes does not change the panel's width and
  // no row is cut off; the content scrolls vertically only.
  widget()->setMinimumWidth(contentWidth());
}

void ShadowPanel::addEntry(SoNode* node, const QString& label) {
  Entry entry;
  entry.node = CoinRef<SoNode>(node);
  entry.name = node->getName().getString();
  auto* page = new QWidget(forms_);
  auto* layout = new QVBoxLayout(page);
  layout->setContentsMargins(0, 0, 0, 0);
  std::map<std::string, CollapsibleSection*> sections;
  for (const FieldSpec& spec : fieldsOf(node)) {
    SoField* field = node->getField(SbName(spec.name));
    if (field == nullptr || !FieldEditor::supports(field)) continue;
    CollapsibleSection*& section = sections[spec.section];
    if (section == nullptr) {
      section = addSection(spec.section, page);
      layout->addWidget(section);
    }
    auto* editor = new FieldEditor(field, spec.range, section);
    editor->onEdited([this] {
      if (edited_) edited_();
    });
    section->form()->addRow(spec.name, editor);
    entry.editors[spec.name] = editor;
  }
  if (node->isOfType(SoDeepShadowLight::getClassTypeId())) {
    // After the map's section: traced shadows take the light's and the method's fields only.
    CollapsibleSection* rays = addSection(kRays, page);
    auto* note = wrappingLabel(
        "method RAYS traces one shadow ray per pixel on the CPU (Embree): exact, no map, so "
        "the Map fields do not apply. AUTO picks it on software rasterisers. method VOLUMES "
        "draws shadow volumes in GL for the same pixels: exact hard shadows, no map either. "
        "method OPACITY_MAP keeps a map of `slices` depth slices instead of maxLayers peeled "
        "layers: a fixed cost, exact only where receivers lie a slice behind their casters.",
        rays);
    rays->form()->addRow(note);
    layout->addWidget(rays);
  }
  layout->addStretch();
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

void ShadowPanel::addToolAction(QAction* action) {
  auto* button = new QToolButton(this);
  button->setDefaultAction(action);
  button->setToolButtonStyle(Qt::ToolButtonTextOnly);
  tools_->addWidget(button);
}

void ShadowPanel::setFigures(const QString& text) {
  figures_->setText(text);
}

}  // namespace ivshadow
