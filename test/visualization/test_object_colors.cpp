// The object palette: deterministic, and distinct colors for different objects.

#include <mid/visualization/object_colors.h>

#include <gtest/gtest.h>

#include <cstdlib>

namespace {

int
distance (const mid::visualization::ObjectColor& a,
          const mid::visualization::ObjectColor& b)
{
  return std::abs (a.r - b.r) + std::abs (a.g - b.g) + std::abs (a.b - b.b);
}

} // namespace

TEST (ObjectColors, AreDeterministicAndDistinct)
{
  using mid::visualization::objectColor;
  for (std::size_t id = 0; id < 40; ++id)
    EXPECT_EQ (distance (objectColor (id), objectColor (id)), 0);
  // The hand-picked palette: every pair clearly apart.
  for (std::size_t a = 0; a < mid::visualization::OBJECT_PALETTE_SIZE; ++a)
    for (std::size_t b = a + 1; b < mid::visualization::OBJECT_PALETTE_SIZE; ++b)
      EXPECT_GT (distance (objectColor (a), objectColor (b)), 100) << a << " vs " << b;
  // Beyond it, neighbours stay apart and no color is dark (the viewer's background is).
  for (std::size_t id = 0; id < 200; ++id) {
    EXPECT_GT (distance (objectColor (id), objectColor (id + 1)), 100) << id;
    const auto color = objectColor (id);
    EXPECT_GE (std::max ({color.r, color.g, color.b}), 200) << id;
  }
}
