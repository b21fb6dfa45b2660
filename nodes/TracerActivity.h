#pragma once

namespace ivshadow {

// What a traced group (renderer TRACER) or traced peeling separator (method TRACER) is doing
// that every other group and peeling separator must know of, process-wide, since the nodes it
// reaches are not only its own:
// - DrawingUntraced: a nested render action draws the shapes it does not trace, over paths
//   from the root through enclosing groups; every group and separator on them renders as a
//   plain separator meanwhile (their maps, peeling and pictures belong to the outer frame).
// - RefineTouch: it touches itself to ask for its refined frame, a notification that changes
//   nothing the group or any enclosing one holds.
class TracerActivity {
 public:
  enum Kind { DrawingUntraced, RefineTouch, kKinds };

  static bool active(Kind kind) { return counts_[kind] > 0; }

  // Marks `kind` active for the scope's lifetime.
  class Scope {
   public:
    explicit Scope(Kind kind) : kind_(kind) { ++counts_[kind_]; }
    ~Scope() { --counts_[kind_]; }
    Scope(const Scope&) = delete;
    Scope& operator=(const Scope&) = delete;

   private:
    Kind kind_;
  };

 private:
  // Per thread: Coin traverses and notifies on the thread that applies the action.
  static inline thread_local int counts_[kKinds] = {};
};

}  // namespace ivshadow
