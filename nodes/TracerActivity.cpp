#include "nodes/TracerActivity.h"

namespace ivshadow {
namespace {

// Per thread: Coin traverses and notifies on the thread that applies the action.
thread_local int counts[TracerActivity::kKinds] = {};

}  // namespace

bool TracerActivity::active(Kind kind) {
  return counts[kind] > 0;
}

TracerActivity::Scope::Scope(Kind kind) : kind_(kind) {
  ++counts[kind_];
}

TracerActivity::Scope::~Scope() {
  --counts[kind_];
}

}  // namespace ivshadow
