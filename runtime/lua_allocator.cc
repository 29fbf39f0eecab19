#include "runtime/lua_allocator.h"

#include <algorithm>
#include <cstdlib>
#include <cstring>

namespace arbc {

LuaAllocator::~LuaAllocator() {
  for (size_t c = 0; c < kClasses; ++c) {
    for (size_t i = 0; i < count_[c]; ++i) std::free(kept_[c][i]);
  }
}

// Small blocks are always allocated at their class's full size, so that any block of a class
// can serve any request of that class.
void* LuaAllocator::obtain(size_t n) {
  if (!small(n)) return std::malloc(n);
  size_t c = class_of(n);
  if (count_[c] > 0) return kept_[c][--count_[c]];
  return std::malloc((c + 1) * kGrain);
}

void LuaAllocator::release(void* p, size_t n) {
  if (small(n)) {
    size_t c = class_of(n);
    if (count_[c] < kKeep) {
      kept_[c][count_[c]++] = p;
      return;
    }
  }
  std::free(p);
}

void* LuaAllocator::resize(void* p, size_t old_size, size_t new_size) {
  if (!small(old_size) && !small(new_size)) return std::realloc(p, new_size);
  if (small(old_size) && small(new_size) && class_of(old_size) == class_of(new_size)) return p;
  void* q = obtain(new_size);
  if (!q) return nullptr;  // p stays valid, as realloc leaves it
  std::memcpy(q, p, std::min(old_size, new_size));
  release(p, old_size);
  return q;
}

void* LuaAllocator::allocate(void* ud, void* ptr, size_t old_size, size_t new_size) {
  auto* self = static_cast<LuaAllocator*>(ud);
  size_t old = ptr ? old_size : 0;  // without a block, old_size is the kind of object
  if (new_size == 0) {
    if (ptr) self->release(ptr, old);
    self->used_ -= old;
    return nullptr;
  }
  if (new_size > old && self->used_ - old + new_size > self->cap_) return nullptr;
  void* p = ptr ? self->resize(ptr, old, new_size) : self->obtain(new_size);
  if (!p) return nullptr;
  self->used_ = self->used_ - old + new_size;
  return p;
}

}  // namespace arbc
