#pragma once

#include <utility>

namespace ivshadow {

// Move-only owner of one GL object name. `Release` deletes a name in the context that is
// current when the owner dies; owners must therefore die while their context is current
// (the headless renderer and, later, per-context caches guarantee that).
template <typename Release>
class GlObject {
 public:
  GlObject() = default;
  explicit GlObject(unsigned int name) : name_(name) {}
  ~GlObject() { reset(); }

  GlObject(const GlObject&) = delete;
  GlObject& operator=(const GlObject&) = delete;
  GlObject(GlObject&& other) noexcept : name_(std::exchange(other.name_, 0u)) {}
  GlObject& operator=(GlObject&& other) noexcept {
    if (this != &other) {
      reset();
      name_ = std::exchange(other.name_, 0u);
    }
    return *this;
  }

  unsigned int get() const { return name_; }
  explicit operator bool() const { return name_ != 0u; }

  void reset() {
    if (name_ != 0u) Release{}(name_);
    name_ = 0u;
  }

 private:
  unsigned int name_ = 0u;
};

}  // namespace ivshadow
