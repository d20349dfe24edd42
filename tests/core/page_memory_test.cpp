// The page_memory seam (page_memory.h) as big_blocks uses it, whichever implementation this build links (the gcc
// build tests the linux one, scripts/clang_build.sh the portable one): blocks are writable to their last byte and
// aligned for any scalar, growing keeps the used bytes and gives writable new ones, a grow that cannot be had
// throws std::bad_alloc and leaves the block as it was, and release takes null.
#include "core/page_memory.h"

#include <gtest/gtest.h>

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <new>

namespace meshedit {
namespace {

constexpr size_t kBytes = size_t(4) << 20;

bool aligned_for_scalars(const void* p) { return reinterpret_cast<uintptr_t>(p) % alignof(std::max_align_t) == 0; }

void fill(void* p, size_t from, size_t to) {
  auto* bytes = static_cast<unsigned char*>(p);
  for (size_t i = from; i < to; ++i) bytes[i] = static_cast<unsigned char>(i * 31 + 7);
}

bool holds_fill(const void* p, size_t from, size_t to) {
  const auto* bytes = static_cast<const unsigned char*>(p);
  for (size_t i = from; i < to; ++i) {
    if (bytes[i] != static_cast<unsigned char>(i * 31 + 7)) return false;
  }
  return true;
}

TEST(PageMemory, BlocksAreAlignedAndWritableToTheirLastByte) {
  for (const size_t bytes : {kBytes, kBytes + 1, kBytes + page_memory::kHugePage + 3}) {
    void* p = page_memory::allocate(bytes);
    ASSERT_NE(p, nullptr);
    EXPECT_TRUE(aligned_for_scalars(p));
    if (page_memory::starts_on_huge_pages()) {
      EXPECT_EQ(reinterpret_cast<uintptr_t>(p) % page_memory::kHugePage, 0u);
    }
    fill(p, 0, bytes);
    EXPECT_TRUE(holds_fill(p, 0, bytes));
    page_memory::release(p, bytes);
  }
}

TEST(PageMemory, GrowingKeepsTheUsedBytesAndGivesWritableNewOnes) {
  void* p = page_memory::allocate(kBytes);
  fill(p, 0, kBytes);
  const size_t used = kBytes - 100;
  size_t bytes = kBytes;
  for (const size_t new_bytes : {kBytes + 1, 3 * kBytes + 12, 8 * kBytes}) {
    p = page_memory::grow(p, bytes, used, new_bytes);
    bytes = new_bytes;
    ASSERT_TRUE(holds_fill(p, 0, used)) << new_bytes << " bytes";
    EXPECT_TRUE(aligned_for_scalars(p));
    std::memset(static_cast<unsigned char*>(p) + used, 0xab, bytes - used);
    EXPECT_EQ(static_cast<unsigned char*>(p)[bytes - 1], 0xab);
    fill(p, 0, used);
  }
  page_memory::release(p, bytes);
}

TEST(PageMemory, AGrowThatCannotBeHadThrowsAndLeavesTheBlockAsItWas) {
  void* p = page_memory::allocate(kBytes);
  fill(p, 0, kBytes);
  EXPECT_THROW(p = page_memory::grow(p, kBytes, kBytes, size_t(1) << 62), std::bad_alloc);  // 4 EiB
  EXPECT_TRUE(holds_fill(p, 0, kBytes));
  EXPECT_THROW(page_memory::allocate(size_t(1) << 62), std::bad_alloc);
  page_memory::release(p, kBytes);
  page_memory::release(nullptr, kBytes);
}

}  // namespace
}  // namespace meshedit
