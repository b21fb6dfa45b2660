#pragma once

#include "scene/CoinRef.h"

#include <QDockWidget>

#include <functional>
#include <map>
#include <string>
#include <vector>

class QComboBox;
class QLabel;
class QStackedWidget;
class SoNode;
class SoSeparator;

namespace ivshadow {

class FieldEditor;
struct FieldAssignment;

// The dock panel of the deep shadow nodes in the scene: pick one SoDeepShadowLight,
// SoTransparentShadowGroup or SoPeelingSeparator from the list and edit its fields
// (resolution, layers, colour mode and model, precision, filter, bias, peel method and cap,
// on/off, ...); every change applies to the scene at once. A scene without any offers one
// button that adds a shadow group with a deep shadow light. Below, the live figures.
class ShadowPanel : public QDockWidget {
 public:
  explicit ShadowPanel(QWidget* parent);
  ~ShadowPanel() override;

  // Lists the deep shadow nodes under `root` (nullptr: none) and binds the editors to them.
  void setScene(SoSeparator* root, const std::string& sceneName);
  // Called when the user asks to add a deep shadow light to a scene that has none.
  void onAddLightRequested(std::function<void()> callback) { addLight_ = std::move(callback); }
  // Called with the node whose fields are shown, whenever that changes.
  void onNodeSelected(std::function<void(SoNode*)> callback) { selected_ = std::move(callback); }
  SoNode* selectedNode() const;
  void selectNode(SoNode* node);

  // Applies NAME.field=VALUE through the editors, exactly as if typed into the panel, to
  // every listed node DEF-named NAME. Throws InputError naming the assignment, the node or
  // field and what was expected when the panel has no such node or field, or cannot take
  // the value.
  void assign(const FieldAssignment& assignment);

  void setFigures(const QString& text);

 private:
  struct Entry {
    CoinRef<SoNode> node;
    std::string name;
    std::map<std::string, FieldEditor*> editors;
  };

  void clear();
  void addEntry(SoNode* node, const QString& label);

  QComboBox* nodes_ = nullptr;
  QStackedWidget* forms_ = nullptr;
  QWidget* emptyPage_ = nullptr;
  QLabel* figures_ = nullptr;
  std::vector<Entry> entries_;
  std::string sceneName_;
  std::function<void()> addLight_;
  std::function<void(SoNode*)> selected_;
};

}  // namespace ivshadow
