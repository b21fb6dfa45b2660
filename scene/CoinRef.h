#pragma once

#include <utility>

namespace ivshadow {

// Holds one Coin reference (ref() on take, unref() on release) to a node or other SoBase.
template <typename T>
class CoinRef {
 public:
  CoinRef() = default;
  explicit CoinRef(T* object) : object_(object) {
    if (object_) object_->ref();
  }
  ~CoinRef() { reset(); }
  CoinRef(const CoinRef& other) : CoinRef(other.object_) {}
  CoinRef& operator=(const CoinRef& other) {
    CoinRef copy(other);
    std::swap(object_, copy.object_);
    return *this;
  }
  CoinRef(CoinRef&& other) noexcept : object_(std::exchange(other.object_, nullptr)) {}
  CoinRef& operator=(CoinRef&& other) noexcept {
    std::swap(object_, other.object_);
    return *this;
  }

  T* get() const { return object_; }
  T* operator->() const { return object_; }
  explicit operator bool() const { return object_ != nullptr; }
  void reset() {
    if (object_) object_->unref();
    object_ = nullptr;
  }

 private:
  T* object_ = nullptr;
};

}  // namespace ivshadow
