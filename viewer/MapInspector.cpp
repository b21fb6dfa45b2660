#include "viewer/MapInspector.h"

#include "gl/ShaderConstants.h"
#include "ivshadow/DeepShadowStatistics.h"
#include "ivshadow/ShadowMethod.h"
#include "ivshadow/SoTransparentShadowGroup.h"
#include "nodes/NodesOfType.h"
#include "nodes/ShadowGroupElement.h"
#include "viewer/FocusedWheel.h"

#include <Inventor/actions/SoGLRenderAction.h>
#include <Inventor/actions/SoSearchAction.h>
#include <Inventor/fields/SoSFEnum.h>
#include <Inventor/nodes/SoCallback.h>
#include <Inventor/nodes/SoSeparator.h>

#include <QComboBox>
#include <QFormLayout>
#include <QLabel>
#include <QPixmap>
#include <QScrollArea>
#include <QSignalBlocker>
#include <QSpinBox>
#include <QVBoxLayout>

#include <algorithm>
#include <cmath>

namespace ivshadow {
namespace {

const char* const kFaceNames[6] = {"+x", "-x", "+y", "-y", "+z", "-z"};
constexpr int kShownSize = 256;

// Distances at or above this mark texels where the peel found no surface (the map clears
// them to the largest float).
constexpr float kNoSurface = 1e30f;

struct LightInGroup {
  SoTransparentShadowGroup* group = nullptr;
  int slot = -1;
  DeepShadowLightStatistics stats;
};

// The light at `index` of collectDeepShadowStatistics's list: its group, and its slot there
// (the group's statistics list its lights in slot order).
LightInGroup lightAt(SoSeparator* root, int index) {
  LightInGroup found;
  int seen = 0;
  forEachNodeOfType<SoTransparentShadowGroup>(root, [&](SoTransparentShadowGroup& group) {
    const auto& lights = group.getStatistics().lights;
    if (found.group == nullptr && index < seen + int(lights.size())) {
      found.group = &group;
      found.slot = index - seen;
      found.stats = lights[std::size_t(found.slot)];
    }
    seen += int(lights.size());
  });
  return found;
}

}  // namespace

MapInspector::MapInspector(QWidget* parent) : QDockWidget("Deep shadow map", parent) {
  setObjectName("MapInspector");
  auto* content = new QWidget(this);
  auto* layout = new QVBoxLayout(content);
  auto* form = new QFormLayout;
  lights_ = new FocusedWheel<QComboBox>(content);
  faces_ = new FocusedWheel<QComboBox>(content);
  for (const char* face : kFaceNames) faces_->addItem(face);
  layer_ = new FocusedWheel<QSpinBox>(content);
  layer_->setRange(1, kMaxMapLayers);
  mode_ = new FocusedWheel<QComboBox>(content);
  mode_->addItems({"depth", "visibility"});
  form->addRow("light", lights_);
  form->addRow("face (F1-F6)", faces_);
  form->addRow("layer (1-9)", layer_);
  form->addRow("show", mode_);
  layout->addLayout(form);
  image_ = new QLabel(content);
  image_->setFixedSize(kShownSize, kShownSize);
  image_->setAlignment(Qt::AlignCenter);
  layout->addWidget(image_);
  // As wide as the picture and as high as its wrapped text needs: a wrapping label sized by
  // the dock alone was given one line's height and ran over the picture.
  status_ = new QLabel(content);
  status_->setWordWrap(true);
  status_->setFixedWidth(kShownSize);
  status_->setAlignment(Qt::AlignLeft | Qt::AlignTop);
  status_->setSizePolicy(QSizePolicy::Fixed, QSizePolicy::Minimum);
  layout->addWidget(status_);
  layout->addStretch();
  // Scrolls when the dock is shorter than the picture and its text.
  auto* scroll = new QScrollArea(this);
  scroll->setWidget(content);
  scroll->setWidgetResizable(true);
  scroll->setFrameShape(QFrame::NoFrame);
  setWidget(scroll);

  const auto changed = [this] { request(); };
  connect(lights_, QOverload<int>::of(&QComboBox::currentIndexChanged), this, [this] {
    wantedLight_.clear();
    request();
  });
  connect(faces_, QOverload<int>::of(&QComboBox::currentIndexChanged), this, changed);
  connect(layer_, QOverload<int>::of(&QSpinBox::valueChanged), this, changed);
  connect(mode_, QOverload<int>::of(&QComboBox::currentIndexChanged), this,
          [this] { showReadback(); });
}

MapInspector::~MapInspector() {
  detachProbe();
}

void MapInspector::setScene(SoSeparator* root) {
  detachProbe();
  root_ = CoinRef<SoSeparator>(root);
  {
    const QSignalBlocker block(lights_);
    lights_->clear();
  }
  readback_ = MapLayerReadback();
  picture_ = QImage();
  image_->clear();
  if (isVisible()) request();
}

void MapInspector::showEvent(QShowEvent* event) {
  QDockWidget::showEvent(event);
  request();
}

void MapInspector::hideEvent(QHideEvent* event) {
  QDockWidget::hideEvent(event);
  // Hidden, the inspector keeps nothing in the scene: the group goes back to its own
  // children (and rebuilds its maps once).
  detachProbe();
  pending_ = requested_ = false;
}

bool MapInspector::selectLight(const QString& name) {
  refillLights();
  wantedLight_ = name;
  const int index = lights_->findText(name);
  if (index >= 0) lights_->setCurrentIndex(index);
  request();
  return index >= 0 || lights_->count() == 0;
}

void MapInspector::selectFace(int face) {
  faces_->setCurrentIndex(std::clamp(face, 0, 5));
}

void MapInspector::selectLayer(int layer) {
  layer_->setValue(layer);
}

void MapInspector::setShowVisibility(bool visibility) {
  mode_->setCurrentIndex(visibility ? 1 : 0);
}

QString MapInspector::status() const {
  return statusText_;
}

void MapInspector::refillLights() {
  if (!root_) return;
  const DeepShadowStatistics stats = collectDeepShadowStatistics(root_.get());
  QStringList names;
  for (std::size_t i = 0; i < stats.lights.size(); ++i) {
    const std::string& name = stats.lights[i].name;
    names << (name.empty() ? QString("light %1").arg(i + 1) : QString::fromStdString(name));
  }
  QStringList current;
  for (int i = 0; i < lights_->count(); ++i) current << lights_->itemText(i);
  if (names == current) return;
  const QString selected = wantedLight_.isEmpty() ? lights_->currentText() : wantedLight_;
  const QSignalBlocker block(lights_);
  lights_->clear();
  lights_->addItems(names);
  const int index = lights_->findText(selected);
  lights_->setCurrentIndex(index >= 0 ? index : 0);
}

void MapInspector::request() {
  if (!isVisible() || !root_) return;
  pending_ = true;
  refillLights();
  if (!probe_ || !group_) {
    // The maps are known only once a group has built them; until then the probe waits in
    // the first group, where most scenes have their lights.
    const LightInGroup light = lightAt(root_.get(), std::max(0, lights_->currentIndex()));
    if (light.group != nullptr) {
      group_ = CoinRef<SoTransparentShadowGroup>(light.group);
    } else {
      forEachNodeOfType<SoTransparentShadowGroup>(root_.get(), [this](SoTransparentShadowGroup& g) {
        if (!group_) group_ = CoinRef<SoTransparentShadowGroup>(&g);
      });
    }
    attachProbe();
  }
  if (redraw_) redraw_();
}

void MapInspector::attachProbe() {
  if (!group_) {
    statusText_ = "The scene has no TransparentShadowGroup, so no deep shadow map.";
    showStatus(statusText_);
    pending_ = false;
    return;
  }
  if (!probe_) {
    probe_ = CoinRef<SoCallback>(new SoCallback);
    probe_->setName("IvShadowViewerMapProbe");
    probe_->setCallback(&MapInspector::probe, this);
  }
  if (group_->findChild(probe_.get()) < 0) group_->addChild(probe_.get());
}

void MapInspector::detachProbe() {
  if (group_ && probe_) {
    const int index = group_->findChild(probe_.get());
    if (index >= 0) group_->removeChild(index);
  }
  group_.reset();
}

void MapInspector::probe(void* self, SoAction* action) {
  auto* that = static_cast<MapInspector*>(self);
  if (!that->requested_ || !action->isOfType(SoGLRenderAction::getClassTypeId())) return;
  // The group's maps are bound only while it shades its children, not while it captures
  // surfaces for a RAYS light.
  SoState* state = action->getState();
  if (ShadowGroupElement::activeGroup(state) == nullptr || ShadowGroupElement::capturing(state))
    return;
  that->requested_ = false;
  that->readOk_ = readBoundMapLayer(that->slot_, that->arrayLayer_, that->readback_, that->whyNot_);
  that->readDone_ = true;
}

void MapInspector::showStatus(const QString& text) {
  statusText_ = text;
  status_->setText(text);
  // The label's height follows its wrapped text at its fixed width.
  status_->setMinimumHeight(status_->heightForWidth(kShownSize));
}

QString MapInspector::whyNoMap(SoTransparentShadowGroup* group,
                               const DeepShadowLightStatistics* light) const {
  if (group == nullptr) return {};
  const QString groupName = group->getName().getLength() > 0
                                ? QString("The group '%1'").arg(group->getName().getString())
                                : QString("The shadow group");
  const int renderer = group->renderer.getValue();
  if (renderer == SoTransparentShadowGroup::TRACER ||
      (renderer == SoTransparentShadowGroup::AUTO_RENDERER && softwareRenderer_)) {
    return groupName +
           (renderer == SoTransparentShadowGroup::TRACER
                ? QString(" has renderer TRACER")
                : QString(" has renderer AUTO, which chose TRACER on this software rasteriser")) +
           ": it is traced on the CPU with its shadows, and its lights keep no map. To see a "
           "map, set the group's renderer to RASTER and the light's method to MAP.";
  }
  if (light == nullptr || !shadowsPerPixel(light->method)) return {};
  // The light's own method field, or the group's for the lights it casts with its fields.
  SoFieldContainer* owner = group;
  if (!light->name.empty()) {
    SoSearchAction search;
    search.setName(SbName(light->name.c_str()));
    search.setInterest(SoSearchAction::FIRST);
    search.apply(group);
    if (search.getPath() != nullptr && search.getPath()->getTail()->getField("method") != nullptr)
      owner = search.getPath()->getTail();
  }
  const auto* method = static_cast<const SoSFEnum*>(owner->getField("method"));
  const bool chosen = method != nullptr && method->getValue() == 0;
  const QString resolved = shadowMethodName(light->method);
  return QString("%1 %2, so it keeps no map. To see one, set its method to MAP.")
      .arg(lights_->currentText(),
           chosen ? QString("has method AUTO, which chose %1 (%2) on this software rasteriser")
                        .arg(resolved, light->method == ShadowMethod::Volumes
                                           ? "shadow volumes"
                                           : "shadow rays traced per pixel")
                  : QString("has method %1").arg(resolved));
}

void MapInspector::frameDrawn(int rebuilds, bool softwareRenderer) {
  softwareRenderer_ = softwareRenderer;
  if (!isVisible() || !root_) return;
  if (readDone_) {
    readDone_ = false;
    showReadback();
  }
  // A field change or a dragged light rebuilt the maps: what is shown is out of date.
  if (rebuilds != rebuilds_ && !requested_) pending_ = true;
  rebuilds_ = rebuilds;
  if (!pending_) return;
  // A traced group keeps no maps at all, whatever its lights' statistics kept from before.
  {
    SoTransparentShadowGroup* traced = nullptr;
    const LightInGroup selected = lightAt(root_.get(), std::max(0, lights_->currentIndex()));
    if (selected.group != nullptr) {
      traced = selected.group;
    } else {
      forEachNodeOfType<SoTransparentShadowGroup>(root_.get(), [&](SoTransparentShadowGroup& g) {
        if (traced == nullptr) traced = &g;
      });
    }
    const QString why = whyNoMap(traced, nullptr);
    if (!why.isEmpty()) {
      showStatus(why);
      pending_ = false;
      picture_ = QImage();
      image_->clear();
      return;
    }
  }
  // Whatever the maps hold now: the group has built them during the frame just drawn.
  refillLights();
  if (!wantedLight_.isEmpty() && lights_->count() > 0 && lights_->findText(wantedLight_) < 0) {
    QStringList names;
    for (int i = 0; i < lights_->count(); ++i) names << lights_->itemText(i);
    statusText_ = QString("no deep shadow light named '%1' has a map (lights: %2)")
                      .arg(wantedLight_, names.join(", "));
    showStatus(statusText_);
    pending_ = false;
    return;
  }
  const LightInGroup light = lightAt(root_.get(), std::max(0, lights_->currentIndex()));
  if (light.group == nullptr) {
    statusText_ = "No deep shadow map has been built yet (no light that is on?).";
    showStatus(statusText_);
    pending_ = false;
    return;
  }
  if (light.group != group_.get()) {
    detachProbe();
    group_ = CoinRef<SoTransparentShadowGroup>(light.group);
    attachProbe();
  }
  if (light.stats.method == ShadowMethod::OpacityMap) {
    // Its layers are slices of absorbed light and one opaque depth per face, not the
    // distance and visibility pairs the view draws.
    statusText_ = QString(
                      "%1 keeps an opacity map (method OPACITY_MAP), which the inspector "
                      "does not show; method MAP keeps a deep shadow map it shows.")
                      .arg(lights_->currentText());
    showStatus(statusText_);
    pending_ = false;
    picture_ = QImage();
    image_->clear();
    return;
  }
  const int face = faces_->currentIndex();
  const int layers = light.stats.layersUsed[std::size_t(face)];
  {
    const QSignalBlocker block(layer_);
    layer_->setMaximum(std::max(1, layers));
  }
  pending_ = false;
  if (layer_->value() > layers) {
    int total = 0;
    for (int used : light.stats.layersUsed) total += used;
    statusText_ = QString("%1 face %2 holds %3 layers; layer %4 is empty.")
                      .arg(lights_->currentText(), kFaceNames[face])
                      .arg(layers)
                      .arg(layer_->value());
    // A light that traces shadow rays (method RAYS, or AUTO on a software rasteriser)
    // keeps no map at all: say which, and how to get one.
    if (total == 0) {
      const QString why = whyNoMap(light.group, &light.stats);
      statusText_ += " " + (why.isEmpty() ? QString("The light keeps no map.") : why);
    }
    showStatus(statusText_);
    picture_ = QImage();
    image_->clear();
    return;
  }
  int first = 0;
  for (int f = 0; f < face; ++f) first += light.stats.layersUsed[std::size_t(f)];
  slot_ = light.slot;
  arrayLayer_ = first + layer_->value() - 1;
  requested_ = true;
  if (redraw_) redraw_();
}

void MapInspector::showReadback() {
  if (!readOk_) {
    statusText_ = "Cannot read the map: " + QString::fromStdString(whyNot_);
    showStatus(statusText_);
    return;
  }
  const int size = readback_.size;
  if (size <= 0) return;
  const bool visibility = mode_->currentIndex() == 1;
  float nearest = kNoSurface, farthest = 0.0f;
  for (float d : readback_.depth) {
    if (d < kNoSurface) {
      nearest = std::min(nearest, d);
      farthest = std::max(farthest, d);
    }
  }
  picture_ = QImage(size, size, QImage::Format_RGB888);
  const auto byte = [](float v) { return int(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f)); };
  for (int y = 0; y < size; ++y) {
    // Read back bottom row first; pictures go top row first.
    const std::size_t row = std::size_t(size - 1 - y) * std::size_t(size);
    for (int x = 0; x < size; ++x) {
      const std::size_t i = row + std::size_t(x);
      const float depth = readback_.depth[i];
      QRgb colour = qRgb(0, 0, 64);
      if (depth < kNoSurface) {
        if (visibility) {
          const float* v = &readback_.visibility[i * std::size_t(readback_.channels)];
          colour = readback_.channels == 3 ? qRgb(byte(v[0]), byte(v[1]), byte(v[2]))
                                           : qRgb(byte(v[0]), byte(v[0]), byte(v[0]));
        } else {
          const float span = farthest > nearest ? farthest - nearest : 1.0f;
          const int grey = byte(1.0f - 0.8f * (depth - nearest) / span);
          colour = qRgb(grey, grey, grey);
        }
      }
      picture_.setPixel(x, y, colour);
    }
  }
  image_->setPixmap(QPixmap::fromImage(
      picture_.scaled(kShownSize, kShownSize, Qt::IgnoreAspectRatio, Qt::FastTransformation)));
  // The texel on the face's axis, where the distance is the plain distance from the light.
  const std::size_t centre = std::size_t(size / 2) * std::size_t(size) + std::size_t(size / 2);
  const float centreDepth = readback_.depth[centre];
  QString centreText = "no surface";
  if (centreDepth < kNoSurface) {
    const float* v = &readback_.visibility[centre * std::size_t(readback_.channels)];
    centreText =
        QString("depth %1, visibility %2").arg(centreDepth, 0, 'f', 4).arg(v[0], 0, 'f', 4);
    if (readback_.channels == 3)
      centreText += QString(" %1 %2").arg(v[1], 0, 'f', 4).arg(v[2], 0, 'f', 4);
  }
  statusText_ = QString("%1 face %2 layer %3: %4 x %4 texels, depth %5 to %6; centre texel: %7")
                    .arg(lights_->currentText(), kFaceNames[faces_->currentIndex()])
                    .arg(layer_->value())
                    .arg(size)
                    .arg(nearest < kNoSurface ? nearest : 0.0f, 0, 'f', 3)
                    .arg(farthest, 0, 'f', 3)
                    .arg(centreText);
  showStatus(statusText_);
}

MapInspector::Hidden::Hidden(MapInspector& inspector)
    : inspector_(inspector), attached_(bool(inspector.group_)) {
  if (attached_) {
    const int index = inspector_.group_->findChild(inspector_.probe_.get());
    if (index >= 0) inspector_.group_->removeChild(index);
  }
}

MapInspector::Hidden::~Hidden() {
  if (attached_) inspector_.attachProbe();
}

}  // namespace ivshadow
