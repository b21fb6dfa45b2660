#pragma once

#include <string>
#include <vector>

class SoNode;

namespace ivshadow {

// FreeCAD's own node types, which its exports (Gui.export, ActiveView.dump) name with their
// fields declared (`fields [ ... ]`): Coin reads a type it does not know as an unknown node that
// draws nothing, children and all. Registered before a file is read, each reads as its Coin base
// class (SoFCSelectionRoot a Separator, SoBrepFaceSet an IndexedFaceSet, ...), keeping the fields
// the file declares, so that an exported document renders. A type already known to the process
// (FreeCAD's own, where it runs) is left alone.
void registerForeignNodes();

// One warning per node type that Coin read as unknown below `root` ("FILE: warning: ..."): it
// draws nothing, nor anything inside it, and a picture missing a part must not pass unsaid.
std::vector<std::string> unknownNodeWarnings(SoNode* root, const std::string& file);

}  // namespace ivshadow
