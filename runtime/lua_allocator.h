// The allocator of a sandbox's lua_State (docs/runtime.md#the-sandbox): it counts the bytes Lua
// holds against the state's cap, and keeps freed small blocks for reuse.
//
// A message reaches a monitor as fresh tables (runtime/lua_value.h) that the next minor
// collection frees in a batch: a few small blocks per message, more at once than the C
// library's per-thread cache keeps. Reusing them from per-size lists keeps that churn out of
// malloc. At most kKeep blocks of each size class are kept, so the memory held beyond what Lua
// counts stays bounded (a few KiB per monitor).
#pragma once

#include <array>
#include <cstddef>

namespace arbc {

class LuaAllocator {
 public:
  explicit LuaAllocator(size_t cap) : cap_(cap) {}
  ~LuaAllocator();
  LuaAllocator(const LuaAllocator&) = delete;
  LuaAllocator& operator=(const LuaAllocator&) = delete;

  // A lua_Alloc; `ud` is the LuaAllocator. Refuses (nullptr) to grow beyond the cap.
  static void* allocate(void* ud, void* ptr, size_t old_size, size_t new_size);
  size_t used() const { return used_; }  // bytes Lua holds

 private:
  static constexpr size_t kGrain = 16;   // size classes: 16, 32, ... bytes
  static constexpr size_t kClasses = 8;  // up to 128 bytes (tables, nodes, short strings)
  static constexpr size_t kKeep = 64;    // kept blocks per class
  static bool small(size_t n) { return n <= kGrain * kClasses; }
  static size_t class_of(size_t n) { return (n - 1) / kGrain; }
  void* obtain(size_t n);           // a block of at least n bytes
  void release(void* p, size_t n);  // n: the size it was obtained for
  void* resize(void* p, size_t old_size, size_t new_size);

  size_t used_ = 0;
  size_t cap_;
  std::array<std::array<void*, kKeep>, kClasses> kept_{};
  std::array<size_t, kClasses> count_{};
};

}  // namespace arbc
