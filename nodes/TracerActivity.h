#pragma once

#include "ivshadow/Export.h"

namespace ivshadow {

// What a traced group (renderer TRACER) or traced peeling separator (method TRACER) is doing
// that every other group and peeling separator must know of, process-wide, since the nodes it
// reaches are not only its own:
// - DrawingUntraced: a nested render action draws the shapes it does not trace, over paths
//   from the root through enclosing groups; every group and separator on them renders as a
//   plain separator meanwhile (their maps, peeling and pictures belong to the outer frame).
// - RefineTouch: it touches itself to ask for its refined frame, a notification that changes
//   nothing the group or any enclosing one holds.
// Kept in the plugin library alone (tools such as the reference's GL overlay open scopes too):
// an inline variable in this header would be one more copy per executable under hidden
// visibility, and the nodes would never see the tools' scopes.
class IVSHADOW_INTERNAL TracerActivity {
 public:
  enum Kind { DrawingUntraced, RefineTouch, kKinds };

  static bool active(Kind kind);

  // Marks `kind` active for the scope's lifetime.
  class IVSHADOW_INTERNAL Scope {
   public:
    explicit Scope(Kind kind);
    ~Scope();
    Scope(const Scope&) = delete;
    Scope& operator=(const Scope&) = delete;

   private:
    Kind kind_;
  };
};

}  // namespace ivshadow
