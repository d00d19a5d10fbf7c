// The huge-page allocator: large blocks mapped on their own at a 2 MiB
// boundary, small ones from the heap, contents kept through growth and copies.
#include <gtest/gtest.h>

#include <cstdint>
#include <numeric>

#include "geometry/huge_page_allocator.h"

namespace pd {
namespace {

TEST(HugePageAllocator, LargeBlocksStartAtAHugePageSmallOnesAtTheHeap) {
  HugeVector<double> small(1000), large(kOwnBlockBytes / sizeof(double) + 7);
  EXPECT_EQ(reinterpret_cast<std::uintptr_t>(large.data()) % huge_pages::kHugePage, 0u);
  std::iota(large.begin(), large.end(), 0.0);
  std::iota(small.begin(), small.end(), 0.0);
  EXPECT_EQ(large.back(), double(large.size() - 1));  // the tail past the last huge page is there
  EXPECT_EQ(small[999], 999.0);
}

TEST(HugePageAllocator, GrowingAndCopyingKeepTheContents) {
  HugeVector<int> v;
  const int n = int(3 * kOwnBlockBytes / sizeof(int));
  for (int i = 0; i < n; ++i) v.push_back(i);  // through the heap into mapped blocks
  const HugeVector<int> copy = v;
  ASSERT_EQ(copy.size(), size_t(n));
  for (int i = 0; i < n; i += 4099) EXPECT_EQ(copy[size_t(i)], i);
  v.clear();
  v.shrink_to_fit();  // unmapped
  EXPECT_EQ(copy[size_t(n - 1)], n - 1);
}

// A freed block is kept and handed to the next request it fits (already
// touched: no fresh pages to fault and zero); release_kept gives them back.
TEST(HugePageAllocator, AFreedBlockServesTheNextRequestItFits) {
  huge_pages::release_kept();
  const size_t n = 2 * kOwnBlockBytes / sizeof(double);
  const void* first = nullptr;
  {
    HugeVector<double> v(n, 1.0);
    first = v.data();
  }
  EXPECT_EQ(huge_pages::kept_bytes(), huge_pages::mapped_length(n * sizeof(double)));
  {
    HugeVector<double> w(n / 2 + 1);  // fits, and is not cut (not less than half)
    EXPECT_EQ(static_cast<const void*>(w.data()), first);
    EXPECT_EQ(huge_pages::kept_bytes(), 0u);
  }
  {
    HugeVector<double> larger(2 * n);  // fits no kept block: mapped afresh
    EXPECT_NE(static_cast<const void*>(larger.data()), first);
  }
  EXPECT_GT(huge_pages::kept_bytes(), 0u);
  huge_pages::release_kept();
  EXPECT_EQ(huge_pages::kept_bytes(), 0u);
}

TEST(HugePageAllocator, MappedLengthIsWholeSmallPages) {
  EXPECT_EQ(huge_pages::mapped_length(1), huge_pages::kPage);
  EXPECT_EQ(huge_pages::mapped_length(huge_pages::kHugePage + 1),
            huge_pages::kHugePage + huge_pages::kPage);
}

}  // namespace
}  // namespace pd
