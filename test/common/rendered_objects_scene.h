#pragma once

#include <mid/simulation/rendered_frame.h>

#include <Eigen/Geometry>
#include <opencv2/core.hpp>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <cstddef>
#include <string>
#include <vector>

namespace mid {
namespace test {

/** \brief One textured box of a rendered test scene. */
struct BoxSpec
{
  /** \brief Image (in the repository's data/textures) on the face towards the camera. */
  std::string texture;
  /** \brief Edge lengths (metres); the textured face is the one with outward normal -z. */
  Eigen::Vector3d size{0.16, 0.11, 0.04};
  /** \brief Model -> camera pose. */
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  /** \brief The image on every face, not only on the one towards the camera: a side face that
    * shows holds keypoints too.
    */
  bool printed_all_around = false;
  /** \brief If not empty, another image (in data/textures) on the side face with outward
    * normal -y, which a camera sees when the box is tilted towards it: a second face whose
    * keypoints a model seen from the front lacks.
    */
  std::string side_texture = {};
};

/** \brief A rendered frame of boxes in front of an untextured background, exactly known. */
struct RenderedObjectsScene
{
  mid::simulation::RenderedFrame frame;
  pcl::PointCloud<pcl::PointXYZRGBA>::Ptr cloud;
  std::vector<BoxSpec> boxes;
};

/** \brief A box pose: centred at (x, y, z) in the camera frame, its textured face turned by
  * `roll` degrees in the image and tilted by `tilt` degrees about the camera's x axis.
  */
Eigen::Isometry3d
boxPose (double x, double y, double z, double roll, double tilt = 0.0);

/** \brief Render the boxes (exact depth, no sensor noise) into a VGA frame and cloud.
  * \param[in] boxes the boxes
  * \param[in] table_depth > 0: an untextured table facing the camera at this depth (metres)
  * behind the boxes, as a table seen from above; 0: empty space (no depth) around them
  * \param[in] view_tilt degrees: the whole scene (boxes and table) turned by this about the
  * camera's x axis through (0, 0, table_depth), a table seen obliquely, its side faces
  * showing; the result's boxes hold the turned poses
  */
RenderedObjectsScene
renderBoxes (const std::vector<BoxSpec>& boxes,
             double table_depth = 0.0,
             double view_tilt = 0.0);

/** \brief Copies of `box` (its prints and size) lying apart on a table at 0.95 m (their
  * textured faces towards the camera), at four fixed places and turns, for boxes of 0.12 x
  * 0.09 m or less: one copy at each of the given places (indices 0 to 3; another throws
  * std::out_of_range). For renderBoxes().
  */
std::vector<BoxSpec>
boxesLyingApart (const BoxSpec& box, const std::vector<std::size_t>& at);

/** \brief Boxes of 0.12 x 0.09 x 0.04 m lying apart on a table at 0.95 m (boxesLyingApart()),
  * rendered, one per print (a texture as in BoxSpec): at the given places (indices 0 to 3), by
  * default the first ones, as many as prints are given.
  */
RenderedObjectsScene
boxesLyingOnATable (const std::vector<const char*>& prints,
                    const std::vector<std::size_t>& at = {0, 1, 2, 3});

/** \brief How much of a box's outline a picture shows: the share of the points along its 12
  * edges (21 per edge, ends included), projected by a pinhole camera, that fall on a non-zero
  * pixel of `mask` (8-bit, the picture's pixels that show a box).
  * \param[out] samples if given, how many of those points fall inside the mask's image
  * \return the share of the points inside the image; 0 if none is
  */
double
shareOfBoxEdgesOn (const cv::Mat& mask,
                   const BoxSpec& box,
                   double fx,
                   double fy,
                   double cx,
                   double cy,
                   std::size_t* samples = nullptr);

/** \brief The box (index into the scene's boxes) most of the given image keypoints lie on, or -1
  * if most lie on the background (or outside the image), and, when `share` is given, the share
  * of the keypoints on that box (0 for -1).
  */
int
boxUnderKeypoints (const RenderedObjectsScene& scene,
                   const std::vector<Eigen::Vector2f>& pixels,
                   double* share = nullptr);

/** \brief Recolour box `box`'s pixels of `cloud` (a colour cloud of the scene's frame) blue,
  * keeping each pixel's grey level (0.299 r + 0.587 g + 0.114 b, up to rounding): the same
  * print in other colours, which grey levels, and so SIFT, cannot tell from the original.
  * \return the number of pixels recoloured
  */
std::size_t
tintKeepingGreyLevels (const RenderedObjectsScene& scene,
                       int box,
                       pcl::PointCloud<pcl::PointXYZRGB>& cloud);

/** \brief The same on the scene's own cloud. */
std::size_t
tintKeepingGreyLevels (RenderedObjectsScene& scene, int box);

/** \brief Repaint box `box`'s pixels of `cloud` (a colour cloud of the scene's frame) as a
  * print of one ink on grey paper, keeping each pixel's grey level: the darkest fifth of the
  * box's pixels (in the scene's own cloud) in the hue of `ink` (a colour direction, r g b),
  * the rest grey. Two products of one brand: one layout and font, other inks.
  */
void
paintInkKeepingGreyLevels (const RenderedObjectsScene& scene,
                           int box,
                           const Eigen::Vector3f& ink,
                           pcl::PointCloud<pcl::PointXYZRGB>& cloud);

/** \brief Mirror the print of box `box`'s face towards the camera (outward normal -z) between
  * x = `x_from` and x = `x_to` of the box's frame, about their middle, in the scene's own
  * cloud: the same layout, inks and contrast, with another word in that part.
  * \return the number of pixels changed
  */
std::size_t
mirrorPrintPart (RenderedObjectsScene& scene, int box, double x_from, double x_to);

} // namespace test
} // namespace mid
