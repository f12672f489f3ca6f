#include <mid/segmentation/touching_surfaces.h>

#include <pcl/console/print.h>

#include <algorithm>
#include <map>

namespace mid {

bool
touchingSurfaces (const pcl::PointCloud<pcl::PointXYZ>& organized,
                  const std::vector<pcl::Indices>& surfaces,
                  float max_step,
                  int min_contact,
                  std::vector<std::pair<std::size_t, std::size_t>>& pairs)
{
  pairs.clear();
  const auto width = static_cast<std::size_t> (organized.width);
  if (width == 0 || organized.size() != width * organized.height) {
    PCL_ERROR ("[mid::touchingSurfaces] The cloud is not organized (width x height != "
               "size).\n");
    return false;
  }
  if (min_contact < 1) {
    PCL_ERROR ("[mid::touchingSurfaces] A border needs one pair of pixels at least.\n");
    return false;
  }
  constexpr int kNone = -1;
  std::vector<int> label (organized.size(), kNone);
  for (std::size_t s = 0; s < surfaces.size(); ++s)
    for (const auto pixel : surfaces[s]) {
      if (pixel < 0 || static_cast<std::size_t> (pixel) >= label.size()) {
        PCL_ERROR ("[mid::touchingSurfaces] Pixel %d is outside the frame.\n",
                   static_cast<int> (pixel));
        return false;
      }
      label[static_cast<std::size_t> (pixel)] = static_cast<int> (s);
    }
  std::map<std::pair<std::size_t, std::size_t>, int> contacts;
  for (std::size_t pixel = 0; pixel < label.size(); ++pixel) {
    if (label[pixel] == kNone)
      continue;
    const bool has_right = (pixel + 1) % width != 0;
    for (const std::size_t next : {has_right ? pixel + 1 : pixel, pixel + width}) {
      if (next == pixel || next >= label.size() || label[next] == kNone ||
          label[next] == label[pixel])
        continue;
      if ((organized[next].getVector3fMap() - organized[pixel].getVector3fMap())
              .norm() < max_step) {
        const auto a = static_cast<std::size_t> (label[pixel]);
        const auto b = static_cast<std::size_t> (label[next]);
        ++contacts[{std::min (a, b), std::max (a, b)}];
      }
    }
  }
  for (const auto& [pair, count] : contacts)
    if (count >= min_contact)
      pairs.push_back (pair);
  return true;
}

} // namespace mid
