// BigArrayAllocator (big_array_allocator.h): big arrays start on a huge-page boundary and their mapping ends at the
// last small page they need (no resident tail past the array); small arrays come from the heap; every byte of an
// allocation is writable and a block goes back to the allocator that made it.
#include "core/big_array_allocator.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

namespace meshedit {
namespace {

using big_array_detail::kHugePage;
using big_array_detail::kSmallPage;
using big_array_detail::kThreshold;

TEST(BigArrayAllocator, MappingsEndAtTheLastSmallPageTheArrayNeeds) {
  EXPECT_EQ(big_array_detail::mapped_size(kThreshold), kThreshold);
  EXPECT_EQ(big_array_detail::mapped_size(kThreshold + 1), kThreshold + kSmallPage);
  EXPECT_EQ(big_array_detail::mapped_size(kThreshold + kHugePage - 8), kThreshold + kHugePage);
}

TEST(BigArrayAllocator, BigArraysStartOnAHugePageAndEveryByteIsWritable) {
  BigArrayAllocator<uint32_t> alloc;
  for (const size_t bytes : {kThreshold, kThreshold + 12, kThreshold + kHugePage + kSmallPage + 4}) {
    const size_t n = bytes / sizeof(uint32_t);
    uint32_t* p = alloc.allocate(n);
    EXPECT_EQ(reinterpret_cast<uintptr_t>(p) % kHugePage, 0u) << bytes << " bytes";
    p[0] = 1;
    p[n - 1] = 2;
    EXPECT_EQ(p[0] + p[n - 1], 3u);
    alloc.deallocate(p, n);
  }
}

TEST(BigArrayAllocator, ContainersOfBothSizesKeepTheirValuesAcrossGrowth) {
  std::vector<uint64_t, BigArrayAllocator<uint64_t>> values;
  for (uint64_t i = 0; i < (kThreshold / sizeof(uint64_t)) * 3; ++i) values.push_back(i * 7);
  for (uint64_t i = 0; i < values.size(); i += 4099) ASSERT_EQ(values[i], i * 7);
  EXPECT_EQ(values.back(), (values.size() - 1) * 7);
  values.shrink_to_fit();
  EXPECT_EQ(values[12345], 12345u * 7);
}

}  // namespace
}  // namespace meshedit
