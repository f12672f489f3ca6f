#include <mid/segmentation/occluded_outline.h>

#include <pcl/console/print.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace mid {

bool
occludedOutline (const pcl::PointCloud<pcl::PointXYZ>& organized,
                 const pcl::Indices& pixels,
                 int ring,
                 float step,
                 pcl::Indices& outline,
                 pcl::Indices& hidden)
{
  outline.clear();
  hidden.clear();
  if (!organized.isOrganized() || organized.empty()) {
    PCL_ERROR ("[mid::occludedOutline] The cloud is not organized.\n");
    return false;
  }
  if (ring < 1 || !(step > 0.0f) || !std::isfinite (step)) {
    PCL_ERROR ("[mid::occludedOutline] The ring must be >= 1 pixel and the step "
               "finite and > 0.\n");
    return false;
  }
  const auto size = static_cast<pcl::index_t> (organized.size());
  if (std::any_of (pixels.begin(), pixels.end(), [size] (pcl::index_t p) {
        return p < 0 || p >= size;
      })) {
    PCL_ERROR ("[mid::occludedOutline] A pixel lies outside the cloud.\n");
    return false;
  }
  const int width = static_cast<int> (organized.width);
  const int height = static_cast<int> (organized.height);
  std::vector<std::uint8_t> on (organized.size(), 0);
  for (const auto p : pixels)
    on[static_cast<std::size_t> (p)] = 1;
  const auto index = [width] (int row, int column) {
    return static_cast<std::size_t> (row) * static_cast<std::size_t> (width) +
           static_cast<std::size_t> (column);
  };
  const auto offSurface = [&] (int row, int column) {
    return row >= 0 && row < height && column >= 0 && column < width &&
           on[index (row, column)] == 0;
  };
  for (std::size_t i = 0; i < on.size(); ++i) {
    if (on[i] == 0)
      continue; // each pixel once, whatever `pixels` repeats
    const int row = static_cast<int> (i) / width, column = static_cast<int> (i) % width;
    if (!offSurface (row - 1, column) && !offSurface (row + 1, column) &&
        !offSurface (row, column - 1) && !offSurface (row, column + 1))
      continue;
    outline.push_back (static_cast<pcl::index_t> (i));
    const float depth = organized[i].z;
    bool behind = false;
    for (int r = std::max (0, row - ring);
         !behind && r <= std::min (height - 1, row + ring);
         ++r)
      for (int c = std::max (0, column - ring);
           !behind && c <= std::min (width - 1, column + ring);
           ++c)
        behind = on[index (r, c)] == 0 && organized[index (r, c)].z < depth - step;
    if (behind)
      hidden.push_back (static_cast<pcl::index_t> (i));
  }
  return true;
}

bool
occludedOutlineShare (const pcl::PointCloud<pcl::PointXYZ>& organized,
                      const pcl::Indices& pixels,
                      int ring,
                      float step,
                      float& share)
{
  share = 0.0f;
  pcl::Indices outline, hidden;
  if (!occludedOutline (organized, pixels, ring, step, outline, hidden))
    return false;
  if (!outline.empty())
    share = static_cast<float> (hidden.size()) / static_cast<float> (outline.size());
  return true;
}

} // namespace mid
