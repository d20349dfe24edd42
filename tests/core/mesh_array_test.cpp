// MeshArray (mesh_array.h) on big_blocks (big_blocks.h): big arrays start on a huge-page boundary where the
// page_memory seam maps them (Linux) and their mapping ends at the last small page they need; values survive every kind
// of growth (heap to heap, heap to mapping, mapping to mapping by moving pages); a grown mapping's new pages are
// writable; copies, moves, assignment, assign, resize and shrink_to_fit keep std::vector's meaning; an allocation that
// fails leaves the array as it was.
#include "core/mesh_array.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <numeric>
#include <vector>

namespace meshedit {
namespace {

using big_blocks::kThreshold;
using page_memory::kHugePage;
using page_memory::kSmallPage;

constexpr size_t kBigCount = kThreshold / sizeof(uint64_t);  // the first element count that is mapped

// On a huge-page boundary, where this build's page_memory seam puts big blocks there (the portable one does not).
bool on_huge_page(const void* p) {
  return !page_memory::starts_on_huge_pages() || reinterpret_cast<uintptr_t>(p) % kHugePage == 0;
}

TEST(MeshArray, MappingsEndAtTheLastSmallPageTheArrayNeeds) {
  EXPECT_EQ(page_memory::mapped_size(kThreshold), kThreshold);
  EXPECT_EQ(page_memory::mapped_size(kThreshold + 1), kThreshold + kSmallPage);
  EXPECT_EQ(page_memory::mapped_size(kThreshold + kHugePage - 8), kThreshold + kHugePage);
}

TEST(MeshArray, BigArraysStartOnAHugePageAndEveryByteIsWritable) {
  for (const size_t bytes : {kThreshold, kThreshold + 12, kThreshold + kHugePage + kSmallPage + 4}) {
    MeshArray<uint32_t> a;
    a.resize_for_overwrite(bytes / sizeof(uint32_t));
    EXPECT_TRUE(on_huge_page(a.data())) << bytes << " bytes";
    a.front() = 1;
    a.back() = 2;
    EXPECT_EQ(a.front() + a.back(), 3u);
  }
}

TEST(MeshArray, AppendsKeepTheirValuesFromTheHeapIntoMappingsAndAcrossMappings) {
  MeshArray<uint64_t> values;
  std::vector<const uint64_t*> blocks;
  for (uint64_t i = 0; i < kBigCount * 5; ++i) {
    if (values.size() == values.capacity()) blocks.push_back(values.data());
    values.push_back(i * 7);
  }
  ASSERT_EQ(values.size(), kBigCount * 5);
  for (uint64_t i = 0; i < values.size(); ++i) ASSERT_EQ(values[i], i * 7) << i;
  EXPECT_TRUE(on_huge_page(values.data()));
  EXPECT_GE(values.capacity(), values.size());
  EXPECT_GT(blocks.size(), 3u);  // it grew within the heap, into a mapping and between mappings
}

TEST(MeshArray, AMappedArrayGrowsWithItsValuesAndWritableNewPages) {
  MeshArray<uint64_t> a;
  a.resize_for_overwrite(kBigCount + 100);
  std::iota(a.begin(), a.end(), uint64_t(5));
  a.reserve(a.size() * 3 + kHugePage);
  EXPECT_TRUE(on_huge_page(a.data()));
  for (uint64_t i = 0; i < a.size(); ++i) ASSERT_EQ(a[i], i + 5) << i;
  const size_t old = a.size();
  a.resize(a.capacity(), 9);
  for (size_t i = old; i < a.size(); i += 511) ASSERT_EQ(a[i], 9u) << i;
  EXPECT_EQ(a.back(), 9u);
  EXPECT_EQ(a[old - 1], old - 1 + 5);
}

TEST(MeshArray, ResizeValueInitialisesAndResizeForOverwriteKeepsWhatIsThere) {
  MeshArray<int> a{1, 2, 3};
  a.resize(5);
  EXPECT_EQ(a, (MeshArray<int>{1, 2, 3, 0, 0}));
  a.resize(2);
  a.resize_for_overwrite(4);  // within capacity: the old values are still in the memory
  EXPECT_EQ(a[2], 3);
  a.resize(6, a[0]);  // a value from the array itself, across a regrow
  EXPECT_EQ(a[5], 1);
  a.clear();
  EXPECT_TRUE(a.empty());
  EXPECT_GE(a.capacity(), 6u);
}

TEST(MeshArray, CopiesMovesAndAssignmentMeanWhatTheyDoForVectors) {
  MeshArray<uint64_t> big;
  big.resize_for_overwrite(kBigCount * 2);
  std::iota(big.begin(), big.end(), uint64_t(1));
  big.reserve(big.size() * 2);

  MeshArray<uint64_t> copy(big);
  EXPECT_EQ(copy, big);
  EXPECT_EQ(copy.capacity(), big.size());  // copies are exact
  copy[17] = 0;
  EXPECT_NE(copy, big);

  MeshArray<uint64_t> small{4, 5};
  small = big;  // needs a bigger block
  EXPECT_EQ(small, big);
  small = MeshArray<uint64_t>{8, 9, 10};  // move-assigned: takes the small block
  EXPECT_EQ(small, (MeshArray<uint64_t>{8, 9, 10}));
  EXPECT_EQ(small.capacity(), 3u);

  MeshArray<uint64_t> moved(std::move(copy));
  EXPECT_EQ(moved.size(), big.size());
  EXPECT_TRUE(copy.empty());
  EXPECT_EQ(copy.data(), nullptr);
  MeshArray<uint64_t>& same = moved;  // through a reference: clang's -Wself-move flags the direct spelling
  moved = std::move(same);            // self-move keeps the contents
  EXPECT_EQ(moved.size(), big.size());

  const uint64_t* before = big.data();
  MeshArray<uint64_t> shorter{1, 2, 3};
  big = shorter;  // fits: the block is reused
  EXPECT_EQ(big.data(), before);
  EXPECT_EQ(big, shorter);
  big.shrink_to_fit();
  EXPECT_EQ(big.capacity(), 3u);
  EXPECT_EQ(big, shorter);
}

TEST(MeshArray, AssignReplacesTheContents) {
  MeshArray<int> a{7, 7, 7, 7};
  const std::vector<int> source{1, 2, 3, 4, 5, 6};
  a.assign(source.begin(), source.end());
  EXPECT_EQ(a, (MeshArray<int>{1, 2, 3, 4, 5, 6}));
  a.assign(size_t(2), 9);
  EXPECT_EQ(a, (MeshArray<int>{9, 9}));
  a.assign(size_t(40), a[0]);
  EXPECT_EQ(a.size(), 40u);
  EXPECT_EQ(a[39], 9);
}

TEST(MeshArray, AFailedAllocationLeavesTheArrayAsItWas) {
  MeshArray<uint64_t> a{1, 2, 3};
  const uint64_t* block = a.data();
  EXPECT_THROW(a.reserve(size_t(1) << 60), std::bad_alloc);  // 8 EiB: no machine maps that
  EXPECT_EQ(a.data(), block);
  EXPECT_EQ(a, (MeshArray<uint64_t>{1, 2, 3}));
  EXPECT_EQ(a.capacity(), 3u);
}

}  // namespace
}  // namespace meshedit
