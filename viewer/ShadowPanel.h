#pragma once

#include "scene/CoinRef.h"

#include <QDockWidget>
#include <QStringList>

#include <functional>
#include <map>
#include <string>
#include <vector>

class QAction;
class QCheckBox;
class QComboBox;
class QLayout;
class QLabel;
class QStackedWidget;
class SoNode;
class SoSeparator;

namespace ivshadow {

class CollapsibleSection;
class FieldEditor;
struct FieldAssignment;

// The dock panel of the deep shadow nodes in the scene: pick one SoDeepShadowLight,
// SoTransparentShadowGroup or SoPeelingSeparator from the list and edit its fields, grouped
// in sections that fold away (Light, Shadow method, Map, Rays, Peeling); every change applies
// to the scene at once. A scene without any offers one button that adds shadows (and, if
// asked, a ground that catches them). The live figures (section Figures) come first, under the
// node list, so that they are seen without scrolling. The content scrolls when the window is
// too short, and the dock is as wide as its content.
class ShadowPanel : public QDockWidget {
 public:
  explicit ShadowPanel(QWidget* parent);
  ~ShadowPanel() override;

  // Lists the deep shadow nodes under `root` (nullptr: none) and binds the editors to them.
  void setScene(SoSeparator* root, const std::string& sceneName);
  // Called when the user asks to add shadows to a scene that has no deep shadow nodes, with
  // whether to add a ground that catches them (and a fill light) too.
  void onAddShadowsRequested(std::function<void(bool ground)> callback) {
    addShadows_ = std::move(callback);
  }
  // Called after each value the user (or --set) writes through an editor.
  void onFieldEdited(std::function<void()> callback) { edited_ = std::move(callback); }
  // Shows `action` as a button under the node list (the viewer's Move Light).
  void addToolAction(QAction* action);
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

  // Titles of the sections the user folded, kept for every node's page and between runs.
  QStringList collapsedSections() const;
  void setCollapsedSections(const QStringList& titles);

  // The width at which every row shows whole, a vertical scroll bar included.
  int contentWidth() const;

 private:
  struct Entry {
    CoinRef<SoNode> node;
    std::string name;
    std::map<std::string, FieldEditor*> editors;
  };

  void clear();
  void addEntry(SoNode* node, const QString& label);
  CollapsibleSection* addSection(const QString& title, QWidget* parent);
  std::vector<CollapsibleSection*> sections() const;

  QComboBox* nodes_ = nullptr;
  QStackedWidget* forms_ = nullptr;
  QWidget* emptyPage_ = nullptr;
  QLabel* figures_ = nullptr;
  QStringList collapsed_;
  std::vector<Entry> entries_;
  std::string sceneName_;
  std::function<void(bool)> addShadows_;
  std::function<void()> edited_;
  QCheckBox* ground_ = nullptr;
  QLayout* tools_ = nullptr;
  std::function<void(SoNode*)> selected_;
};

}  // namespace ivshadow
