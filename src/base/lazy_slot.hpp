// LazySlot<T>: room for one T, made on demand. Unlike std::optional (whose storage GCC clears when it is
// made), making a LazySlot writes only its flag: objects made once per edge hold kilobytes of such caches.
#pragma once

#include <memory>
#include <type_traits>
#include <utility>

namespace hocav {

template <class T>
class LazySlot {
  static_assert(std::is_trivially_destructible_v<T>, "the slot never destroys its value");

 public:
  LazySlot() {}

  explicit operator bool() const { return filled_; }
  const T& operator*() const { return storage_.value; }

  template <class... Args>
  const T& emplace(Args&&... args) {
    std::construct_at(&storage_.value, std::forward<Args>(args)...);
    filled_ = true;
    return storage_.value;
  }
  void reset() { filled_ = false; }

 private:
  union Storage {
    Storage() {}
    T value;
  } storage_;
  bool filled_ = false;
};

}  // namespace hocav
