#pragma once

#include "gl/DeepShadowMapReadback.h"
#include "ivshadow/DeepShadowStatistics.h"
#include "scene/CoinRef.h"

#include <QDockWidget>
#include <QImage>

#include <functional>
#include <string>

class QComboBox;
class QLabel;
class QSpinBox;
class SoAction;
class SoCallback;
class SoSeparator;
class SoTransparentShadowGroup;

namespace ivshadow {

// A dock that shows one layer of one cube face of a deep shadow map, as the depth of the
// surfaces peeled into it (near bright, far dark, texels without a surface dark blue) or the
// visibility after them (the light's colour getting through), as seeds/000's demo did: D
// shows or hides it, F1-F6 pick the face (+x -x +y -y +z -z), 1-9 the layer.
//
// The maps live in the GL context of the group that built them and are bound only while
// the group draws its children, so an SoCallback (the probe) is added as the group's last
// child while the inspector is open; it reads the requested layer back during the next
// frame. Adding and removing the probe changes the group, which rebuilds its maps once.
class MapInspector : public QDockWidget {
 public:
  explicit MapInspector(QWidget* parent);
  ~MapInspector() override;

  // The scene whose lights are offered; nullptr: none. Call before the scene changes.
  void setScene(SoSeparator* root);
  // Call after each frame with the maps' rebuild count (DeepShadowStatistics::rebuilds): shows
  // what the probe read during the frame, and reads again when the maps were rebuilt.
  // `softwareRenderer`: the GL is a software rasteriser, where AUTO traces on the CPU.
  void frameDrawn(int rebuilds, bool softwareRenderer);
  void selectFace(int face);
  void selectLayer(int layer);
  // The reason the last read failed, or what it showed ("light Lamp +x layer 1 ...").
  QString status() const;
  // The picture shown (size x size texels), null before the first read.
  const QImage& picture() const { return picture_; }
  void setShowVisibility(bool visibility);
  // Picks the light by DEF name (or "light N", counted from 1 in traversal order). Returns
  // false when no light of the scene's maps has that name.
  bool selectLight(const QString& name);
  // Called when the inspector needs a frame drawn to read the map during it.
  void onRedrawNeeded(std::function<void()> callback) { redraw_ = std::move(callback); }
  // Whether a read asked for has been shown (or has failed).
  bool upToDate() const { return !pending_ && !requested_ && !readDone_; }

  // Takes the probe out of the scene while an instance lives (e.g. while the scene is
  // written to a file) and puts it back afterwards.
  class Hidden {
   public:
    explicit Hidden(MapInspector& inspector);
    ~Hidden();
    Hidden(const Hidden&) = delete;
    Hidden& operator=(const Hidden&) = delete;

   private:
    MapInspector& inspector_;
    bool attached_;
  };

 protected:
  void showEvent(QShowEvent* event) override;
  void hideEvent(QHideEvent* event) override;

 private:
  static void probe(void* self, SoAction* action);
  void refillLights();
  void request();
  void attachProbe();
  void detachProbe();
  void showReadback();
  void showStatus(const QString& text);
  // Why the group or the light keeps no map, and how to get one; "" when it should have one.
  QString whyNoMap(SoTransparentShadowGroup* group, const DeepShadowLightStatistics* light) const;

  QComboBox* lights_ = nullptr;
  QComboBox* faces_ = nullptr;
  QSpinBox* layer_ = nullptr;
  QComboBox* mode_ = nullptr;
  QLabel* image_ = nullptr;
  QLabel* status_ = nullptr;

  CoinRef<SoSeparator> root_;
  CoinRef<SoCallback> probe_;
  CoinRef<SoTransparentShadowGroup> group_;  // the group the probe is in
  int slot_ = 0;
  int arrayLayer_ = 0;
  int rebuilds_ = -1;       // the maps' rebuild count when the layer was last asked for
  bool pending_ = false;    // a read is wanted, to be asked for once the maps are known
  bool requested_ = false;  // the probe reads during the next frame
  bool readDone_ = false;
  bool readOk_ = false;
  bool softwareRenderer_ = false;
  std::string whyNot_;
  MapLayerReadback readback_;
  QImage picture_;
  QString statusText_;
  QString wantedLight_;
  std::function<void()> redraw_;
};

}  // namespace ivshadow
