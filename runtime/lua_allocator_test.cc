#include "runtime/lua_allocator.h"

#include <gtest/gtest.h>

#include <cstring>
#include <lua.hpp>
#include <map>
#include <random>
#include <vector>

namespace arbc {
namespace {

// Blocks keep their contents across every kind of resize (within a class, across classes,
// small to large and back), the count is the sum of the live sizes, and the cap refuses
// growth only.
TEST(LuaAllocatorTest, KeepsContentsAndCountsLiveBytes) {
  LuaAllocator a(1u << 20);
  struct Block {
    void* p;
    size_t size;
    unsigned char fill;
  };
  std::vector<Block> live;
  std::mt19937 random(5);
  size_t expected = 0;
  auto check = [](const Block& b) {
    for (size_t i = 0; i < b.size; ++i) ASSERT_EQ(static_cast<unsigned char*>(b.p)[i], b.fill);
  };
  for (int step = 0; step < 20000; ++step) {
    size_t size = random() % 3 == 0 ? 100 + random() % 400 : 1 + random() % 140;
    unsigned what = random() % 3;
    if (what == 0 || live.empty()) {
      void* p = LuaAllocator::allocate(&a, nullptr, LUA_TTABLE, size);
      ASSERT_NE(p, nullptr);
      auto fill = static_cast<unsigned char>(random());
      std::memset(p, fill, size);
      live.push_back({p, size, fill});
      expected += size;
    } else {
      size_t k = random() % live.size();
      Block& b = live[k];
      check(b);
      if (what == 1) {
        void* p = LuaAllocator::allocate(&a, b.p, b.size, size);
        ASSERT_NE(p, nullptr);
        for (size_t i = 0; i < std::min(size, b.size); ++i)
          ASSERT_EQ(static_cast<unsigned char*>(p)[i], b.fill) << "resize lost contents";
        std::memset(p, b.fill, size);
        expected = expected - b.size + size;
        b.p = p;
        b.size = size;
      } else {
        EXPECT_EQ(LuaAllocator::allocate(&a, b.p, b.size, 0), nullptr);
        expected -= b.size;
        live.erase(live.begin() + static_cast<long>(k));
      }
    }
    ASSERT_EQ(a.used(), expected);
  }
  for (const Block& b : live) {
    check(b);
    LuaAllocator::allocate(&a, b.p, b.size, 0);
  }
  EXPECT_EQ(a.used(), 0u);

  LuaAllocator capped(100);
  void* p = LuaAllocator::allocate(&capped, nullptr, 0, 80);
  ASSERT_NE(p, nullptr);
  EXPECT_EQ(LuaAllocator::allocate(&capped, p, 80, 120), nullptr);  // growth past the cap
  EXPECT_EQ(capped.used(), 80u);
  void* q = LuaAllocator::allocate(&capped, p, 80, 8);  // shrinking always works
  ASSERT_NE(q, nullptr);
  EXPECT_EQ(capped.used(), 8u);
  LuaAllocator::allocate(&capped, q, 8, 0);
}

// A whole Lua state runs on it: garbage made and collected many times leaves the count where
// it was (blocks reused from the kept lists are counted again), and it is Lua's own count.
TEST(LuaAllocatorTest, RunsALuaStateWithAFlatCount) {
  LuaAllocator a(8u << 20);
  lua_State* L = lua_newstate(&LuaAllocator::allocate, &a);
  ASSERT_NE(L, nullptr);
  luaL_openlibs(L);
  // The first round grows the string table for good; every later one must end where it did.
  size_t after_first = 0;
  for (int round = 0; round < 5; ++round) {
    ASSERT_EQ(luaL_dostring(L,
                            "local t = {} for i = 1, 5000 do t[i] = {x = i, y = {i}, s = 'k' .. i} "
                            "end t = nil"),
              LUA_OK);
    lua_gc(L, LUA_GCCOLLECT);
    if (round == 0) after_first = a.used();
    EXPECT_LE(a.used(), after_first + 1024) << "round " << round;
  }
  EXPECT_EQ(static_cast<size_t>(lua_gc(L, LUA_GCCOUNT)) * 1024 + lua_gc(L, LUA_GCCOUNTB), a.used());
  lua_close(L);
}

}  // namespace
}  // namespace arbc
