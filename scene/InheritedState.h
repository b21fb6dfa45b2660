#pragma once

#include "ivshadow/Export.h"

#include <cstdint>
#include <memory>
#include <vector>

class SoElement;
class SoState;

namespace ivshadow {

// What a traversal state holds, where a shadow group is traversed, that the triangles,
// colours and textures of the shapes below it are made from: material colours and
// transparency, complexity, draw style, shape hints, units, shadow style, textures and their
// coordinates and matrix, coordinates, bindings, profiles, fonts, switch and override values.
// A group is notified only of changes below it; comparing this with the state of each frame
// tells it when a node above it changed its casters. Transforms are left out on purpose: the
// casters are kept in the group's coordinates, which a transform above moves with the lights.
// The camera, viewport and lights are left out too (they change no caster).
class IVSHADOW_INTERNAL InheritedState {
 public:
  InheritedState();
  ~InheritedState();
  InheritedState(InheritedState&& other) noexcept;
  InheritedState& operator=(InheritedState&& other) noexcept;
  InheritedState(const InheritedState&) = delete;
  InheritedState& operator=(const InheritedState&) = delete;

  // The state's values now (an empty InheritedState matches no state).
  static InheritedState capture(SoState* state);
  bool matches(SoState* state) const;
  bool empty() const { return !captured_; }

 private:
  struct ElementCopy {
    int stackIndex = -1;
    std::unique_ptr<SoElement> match;  // Coin's copyMatchInfo, as render caches keep them
  };

  std::vector<ElementCopy> elements_;
  // SoLazyElement has no match copy: its diffuse colours and transparencies are kept as
  // values (packed colours as they are).
  std::vector<float> colours_;
  std::vector<std::uint32_t> packed_;
  bool captured_ = false;
};

}  // namespace ivshadow
