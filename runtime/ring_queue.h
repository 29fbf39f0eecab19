// A first-in first-out queue in one growing ring of slots: pushing and popping allocate
// nothing once it has grown to its working size. A connection's queue of messages is one; a
// std::deque allocated and freed a block every few messages as the queue moved through memory.
#pragma once

#include <cstddef>
#include <utility>
#include <vector>

namespace arbc {

template <class T>
class RingQueue {
 public:
  bool empty() const { return size_ == 0; }
  size_t size() const { return size_; }
  T& front() { return slots_[head_]; }
  // A new last slot, to be filled in place (it holds a default value).
  T& push_back() {
    if (size_ == slots_.size()) grow();
    return slots_[(head_ + size_++) & (slots_.size() - 1)];
  }
  void push_back(T value) { push_back() = std::move(value); }
  // Moves the first value out and pops it. Its slot keeps the moved-from value until it is
  // reused, which holds no memory for the runtime's values (a moved-from string or shared
  // pointer is empty).
  T take_front() {
    T value = std::move(slots_[head_]);
    head_ = (head_ + 1) & (slots_.size() - 1);
    --size_;
    return value;
  }

 private:
  // Doubles the ring (its size stays a power of two), unrolling the queue to the start.
  void grow() {
    std::vector<T> bigger(slots_.empty() ? 8 : slots_.size() * 2);
    for (size_t i = 0; i < size_; ++i) {
      bigger[i] = std::move(slots_[(head_ + i) & (slots_.size() - 1)]);
    }
    slots_ = std::move(bigger);
    head_ = 0;
  }

  std::vector<T> slots_;
  size_t head_ = 0;
  size_t size_ = 0;
};

}  // namespace arbc
