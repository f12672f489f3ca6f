#pragma once

#include <mid/simulation/rendered_frame.h>
#include <mid/simulation/scene.h>

#include <Eigen/Core>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

#include <cstdint>
#include <string>
#include <vector>

namespace mid {
namespace test {

/** \brief A rendered frame of the tabletop recipe (the sample scene's: juice cartons and
  * distractors on a textured table) with Kinect-like noise, and its truth.
  */
struct TabletopFrame
{
  mid::simulation::Scene scene;
  mid::simulation::RenderedFrame rendered;
  pcl::PointCloud<pcl::PointXYZRGBA>::Ptr cloud =
      pcl::make_shared<pcl::PointCloud<pcl::PointXYZRGBA>>();
};

/** \brief Render the tabletop recipe with `cartons` juice cartons and the given seed.
  * \param[in] texture_dir the product photos; empty: the repository's data/textures
  * \return false if the scene cannot be made or rendered
  */
bool
renderTabletopFrame (int cartons,
                     std::uint32_t seed,
                     TabletopFrame& frame,
                     const std::string& texture_dir = "");

/** \brief The scene object most of the given image positions lie on (an index into the
  * scene's objects; -1 for the background, or when no position lies in the image).
  */
int
objectUnderPixels (const TabletopFrame& frame,
                   const std::vector<Eigen::Vector2f>& pixels);

} // namespace test
} // namespace mid
