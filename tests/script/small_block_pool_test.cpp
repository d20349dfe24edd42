// SmallBlockPool, the free lists under LuaRuntime's allocator: blocks are aligned and distinct, come back for
// reuse, keep their contents when they grow or shrink across size classes and across the malloc boundary; and
// a runtime still enforces its memory cap and frees what a script dropped.
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <set>
#include <string>
#include <vector>

#include <lua.hpp>

#include "script/lua_runtime.h"
#include "script/small_block_pool.h"

namespace meshedit {
namespace {

bool aligned(const void* p) { return reinterpret_cast<uintptr_t>(p) % SmallBlockPool::kGranule == 0; }

TEST(SmallBlockPool, BlocksAreAlignedDistinctAndReused) {
  SmallBlockPool pool;
  std::set<void*> seen;
  std::vector<std::pair<void*, size_t>> blocks;
  for (size_t bytes = 1; bytes <= 2 * SmallBlockPool::kMaxBytes; bytes += 7) {
    for (int copy = 0; copy < 300; ++copy) {  // enough to need more than one slab
      void* p = pool.resize(nullptr, 0, bytes);
      ASSERT_NE(p, nullptr);
      EXPECT_TRUE(aligned(p));
      EXPECT_TRUE(seen.insert(p).second) << "block handed out twice";
      std::memset(p, 0xab, bytes);
      blocks.emplace_back(p, bytes);
    }
  }
  for (auto [p, bytes] : blocks) pool.release(p, bytes);
  // A freed small block is the next one its class hands out.
  void* a = pool.resize(nullptr, 0, 80);
  pool.release(a, 80);
  EXPECT_EQ(pool.resize(nullptr, 0, 72), a);  // 72 and 80 bytes share a 16-byte class
  pool.release(nullptr, 80);                  // like free(nullptr)
}

TEST(SmallBlockPool, ResizeKeepsTheContents) {
  SmallBlockPool pool;
  const auto fill = [](void* p, size_t n) {
    for (size_t i = 0; i < n; ++i) static_cast<unsigned char*>(p)[i] = static_cast<unsigned char>(i * 7 + 1);
  };
  const auto intact = [](const void* p, size_t n) {
    for (size_t i = 0; i < n; ++i) {
      if (static_cast<const unsigned char*>(p)[i] != static_cast<unsigned char>(i * 7 + 1)) return false;
    }
    return true;
  };
  void* p = pool.resize(nullptr, 0, 20);
  fill(p, 20);
  EXPECT_EQ(pool.resize(p, 20, 30), p);  // same class: the block stays
  p = pool.resize(p, 30, 200);           // another class
  EXPECT_TRUE(intact(p, 20));
  fill(p, 200);
  p = pool.resize(p, 200, 5000);  // to malloc
  EXPECT_TRUE(intact(p, 200));
  fill(p, 5000);
  p = pool.resize(p, 5000, 9000);  // malloc to malloc
  EXPECT_TRUE(intact(p, 5000));
  p = pool.resize(p, 9000, 100);  // back into the pool
  EXPECT_TRUE(aligned(p));
  EXPECT_TRUE(intact(p, 100));
  pool.release(p, 100);
}

TEST(SmallBlockPool, TheRuntimeCountsWhatScriptsHoldAndStillCapsIt) {
  LuaLimits limits;
  limits.memory_bytes = size_t(32) << 20;
  LuaRuntime lua(limits);
  const size_t start = lua.memory_used();
  lua.run_string("keep = {} for i = 1, 20000 do keep[i] = {x = i, y = i, z = i} end", "t.lua");
  const size_t holding = lua.memory_used();
  EXPECT_GT(holding, start + 20000 * 64);
  lua.run_string("keep = nil collectgarbage('collect')", "t.lua");
  EXPECT_LT(lua.memory_used(), start + 64 * 1024);
  try {
    lua.run_string("local t = {} for i = 1, 1e8 do t[i] = {i} end", "bomb.lua");
    FAIL() << "no memory error";
  } catch (const ScriptError& e) {
    EXPECT_EQ(e.limit(), ScriptError::Limit::Memory) << e.what();
  }
  lua_gc(lua.state(), LUA_GCCOLLECT);  // the bomb's garbage (the next run would trip over it otherwise)
  EXPECT_LT(lua.memory_used(), start + 64 * 1024);
  EXPECT_EQ(lua.run_string("return 1 + 1", "t.lua"), std::vector<std::string>{"2"});
}

}  // namespace
}  // namespace meshedit
