// median() and quantile() against values whose order is known.
#include <mid/segmentation/order_statistics.h>

#include <gtest/gtest.h>

#include <utility>
#include <vector>

TEST (OrderStatistics, MedianIsTheMiddleValueAndTheUpperOfTwo)
{
  std::vector<float> odd = {5.0f, -1.0f, 3.0f, 9.0f, 0.5f};
  EXPECT_FLOAT_EQ (mid::median (odd), 3.0f);
  std::vector<float> even = {4.0f, 1.0f, 3.0f, 2.0f};
  EXPECT_FLOAT_EQ (mid::median (even), 3.0f);
  std::vector<float> one = {7.0f};
  EXPECT_FLOAT_EQ (mid::median (one), 7.0f);
}

TEST (OrderStatistics, QuantileRoundsItsPositionDown)
{
  const std::vector<float> values = {0.4f, 0.0f, 0.9f, 0.2f, 0.1f, 0.3f};
  // Sorted: 0.0 0.1 0.2 0.3 0.4 0.9; position q * 5, rounded down.
  for (const auto& [q, expected] : std::vector<std::pair<float, float>>{
           {0.0f, 0.0f}, {0.5f, 0.2f}, {0.99f, 0.4f}, {1.0f, 0.9f}}) {
    std::vector<float> copy = values;
    EXPECT_FLOAT_EQ (mid::quantile (copy, q), expected) << q;
  }
}
