// largestSizeGroup(): which of a model's measured boxes gives its size, on boxes of known size.
#include <mid/segmentation/model_size.h>

#include <gtest/gtest.h>

#include <vector>

namespace {

/** A box of edges `size` (metres, ascending) fitted to a surface of `pixels` pixels. */
mid::InstanceExtent
measured (const Eigen::Vector3f& size, int pixels)
{
  mid::InstanceExtent extent;
  extent.size = size;
  extent.surface.assign (static_cast<std::size_t> (pixels), 0);
  return extent;
}

const mid::SizeAgreement kAgree (0.006f, 0.03f);

} // namespace

TEST (LargestSizeGroup, PrefersTheBoxAnotherNearlyAgreesWithToTheSmallestSurface)
{
  // A carton of 84 x 87 x 240 mm measured whole twice (the second 6 mm too long: just outside
  // the tolerances), and once hidden in part (the smallest surface). No two agree, so each
  // box is a group of one; a whole one must win.
  const mid::InstanceExtents extents = {measured ({0.084f, 0.087f, 0.240f}, 9000),
                                        measured ({0.087f, 0.087f, 0.248f}, 9500),
                                        measured ({0.048f, 0.087f, 0.132f}, 3000)};
  ASSERT_FALSE (kAgree (extents[0].size, extents[1].size));
  std::size_t representative = 99;
  const std::vector<std::size_t> group =
      mid::largestSizeGroup (extents, {0, 1, 2}, kAgree, representative);
  EXPECT_EQ (representative, 0u); // the smaller surface of the two whole ones
  EXPECT_EQ (group, (std::vector<std::size_t>{0}));
}

TEST (LargestSizeGroup, PrefersTheMostAgreeingThenTheSmallestSurface)
{
  // Two copies agree on the true size; the box of one joined with a neighbour is larger. The
  // group of two wins, represented by its smaller surface.
  const mid::InstanceExtents extents = {measured ({0.087f, 0.198f, 0.351f}, 20000),
                                        measured ({0.084f, 0.087f, 0.240f}, 9000),
                                        measured ({0.085f, 0.086f, 0.238f}, 8000)};
  std::size_t representative = 99;
  const std::vector<std::size_t> group =
      mid::largestSizeGroup (extents, {0, 1, 2}, kAgree, representative);
  EXPECT_EQ (representative, 2u);
  EXPECT_EQ (group, (std::vector<std::size_t>{1, 2}));

  // Among boxes that agree with nothing, even loosely, the smallest surface wins (a surface is
  // more often joined with something than hidden).
  const mid::InstanceExtents apart = {measured ({0.05f, 0.10f, 0.20f}, 9000),
                                      measured ({0.10f, 0.15f, 0.30f}, 12000),
                                      measured ({0.02f, 0.03f, 0.04f}, 500)};
  mid::largestSizeGroup (apart, {0, 1}, kAgree, representative);
  EXPECT_EQ (representative, 0u);
  representative = 99;
  EXPECT_TRUE (mid::largestSizeGroup (apart, {}, kAgree, representative).empty());
  EXPECT_EQ (representative, 99u);
}
