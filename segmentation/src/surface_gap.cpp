#include "image_line.h"

#include <mid/segmentation/surface_gap.h>

#include <algorithm>

namespace mid {

bool
isValidKeypointSurface (const KeypointSurface& surface, std::size_t keypoints)
{
  if (!surface.organized || !surface.organized->isOrganized() ||
      surface.keypoint_pixels.size() != keypoints)
    return false;
  const auto pixels = static_cast<pcl::index_t> (surface.organized->size());
  return std::all_of (surface.keypoint_pixels.begin(),
                      surface.keypoint_pixels.end(),
                      [pixels] (pcl::index_t p) { return p >= 0 && p < pixels; });
}

bool
surfaceDropsBetween (const KeypointSurface& surface,
                     pcl::index_t a,
                     pcl::index_t b,
                     float min_drop,
                     int min_pixels)
{
  // Valid pixels in a row behind the segment (pixels without depth skipped).
  int run = 0;
  bool drops = false;
  detail::walkImageLine (*surface.organized,
                         surface.keypoint_pixels[static_cast<std::size_t> (a)],
                         surface.keypoint_pixels[static_cast<std::size_t> (b)],
                         [&] (pcl::index_t, double behind) {
                           run = behind > min_drop ? run + 1 : 0;
                           drops = run >= std::max (min_pixels, 1);
                           return !drops;
                         });
  return drops;
}

bool
surfacePinhole (const KeypointSurface& surface, FramePinhole& pinhole)
{
  if (surface.pinhole) {
    pinhole = *surface.pinhole;
    return pinhole.isValid();
  }
  return surface.organized && fitFramePinhole (*surface.organized, pinhole);
}

} // namespace mid
