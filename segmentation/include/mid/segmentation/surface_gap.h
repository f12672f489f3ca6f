#pragma once

#include <mid/segmentation/frame_pinhole.h>

#include <pcl/point_cloud.h>
#include <pcl/point_types.h>
#include <pcl/types.h>

#include <array>
#include <memory>
#include <vector>

namespace mid {

/** \brief A pixel's chromaticity: its red and green shares of r + g + b (the colour without
  * its brightness, which shading changes and a white light does not tint).
  */
using Chromaticity = std::array<float, 2>;

/** \brief The frame's organized points and the pixel each keypoint was found at: what a
  * keypoint-only step needs to look at the surface between two keypoints.
  */
struct KeypointSurface
{
  /** \brief The organized frame (camera frame, metres; NaN where the depth is missing). */
  pcl::PointCloud<pcl::PointXYZ>::ConstPtr organized;
  /** \brief For each keypoint of the keypoint cloud, its pixel in `organized` (row * width +
    * column).
    */
  pcl::Indices keypoint_pixels;
  /** \brief The grey level of each pixel of `organized` (any scale, e.g. 0 to 255), or null
    * when the frame has no colour; only the photometric verification of clusters reads it
    * (PhotometricVerification).
    */
  std::shared_ptr<const std::vector<float>> intensity = nullptr;
  /** \brief The chromaticity of each pixel of `organized` (chromaticities(); NaN where the
    * pixel is too dark to tell), or null: the photometric verification then compares grey
    * levels only (PhotometricVerification::setMaxChromaticityDifference()), and
    * SizeInstanceSearch pairs no two objects at its looser size agreement.
    */
  std::shared_ptr<const std::vector<Chromaticity>> chromaticity = nullptr;
  /** \brief The projection of `organized` onto its pixels when known (the camera's intrinsics,
    * or a fit kept for several steps), or null: the steps that project points
    * (PhotometricVerification) then fit it with fitFramePinhole().
    */
  std::shared_ptr<const FramePinhole> pinhole = nullptr;
};

/** \brief The projection of a keypoint surface's frame: KeypointSurface::pinhole when it is
  * given, else one fitted to the organized frame (fitFramePinhole()).
  * \param[in] surface the keypoint surface
  * \param[out] pinhole the projection
  * \return false if the given projection is not valid (FramePinhole::isValid()), or none was
  * given and none fits the frame (or there is no frame)
  */
bool
surfacePinhole (const KeypointSurface& surface, FramePinhole& pinhole);

/** \brief True if `surface` is organized and gives a pixel inside it for each of
  * `keypoints` keypoints.
  */
bool
isValidKeypointSurface (const KeypointSurface& surface, std::size_t keypoints);

/** \brief How far (metres) the surface between two keypoints must fall behind the segment
  * joining them (surfaceDropsBetween()) for the steps that look for a gap between two copies
  * (the compound and chain splitting): the floor or the background seen between them, not the
  * depth noise of one face.
  */
constexpr float kMinSurfaceGapDrop = 0.01f;

/** \brief True if the surface seen between two keypoints falls behind the straight segment
  * joining them by more than `min_drop` somewhere: the two lie on different objects, with
  * something farther from the camera (the floor, the background) between them.
  *
  * Walks the image line between the two keypoints' pixels; at each pixel with a valid point
  * p, compares p's distance from the camera with that of the segment along p's viewing ray
  * (the point of the segment's line closest to the ray). The visible surface of one convex
  * object lies in front of every chord between two of its points, so it never drops; nor does
  * a flat or gently curved face. The drop must hold over `min_pixels` valid pixels in a row:
  * a lone pixel behind the segment is more likely a flying pixel at a depth edge or a bad
  * reading than a gap. Missing depth is ignored (it neither counts nor breaks a run): it
  * does not tell a border from a reflection.
  * \param[in] surface a valid KeypointSurface (isValidKeypointSurface(); not checked)
  * \param[in] a one keypoint (index into the keypoint cloud)
  * \param[in] b another keypoint
  * \param[in] min_drop how far behind the segment (metres, along the viewing ray) the
  * surface must fall
  * \param[in] min_pixels how many valid pixels in a row must fall that far (values below 1
  * count as 1; 3 pixels are 6 mm at 1 m for a 525-pixel focal length)
  * \return false if no min_pixels valid pixels in a row between them fall that far, or either
  * end has no valid point
  */
bool
surfaceDropsBetween (const KeypointSurface& surface,
                     pcl::index_t a,
                     pcl::index_t b,
                     float min_drop,
                     int min_pixels = 3);

} // namespace mid
