#pragma once

#include <mid/simulation/shape.h>

namespace mid {
namespace simulation {

/** \brief A flat table top: the plane z = 0 of its model frame (normal +z, up), either infinite
  * or a rectangle centred at the origin, covered by a tiled texture.
  *
  * One copy of the texture covers tile_x x tile_y metres (true metric scale), centred at the
  * origin, and repeats beyond (so a table whose tile size equals its extent shows the texture
  * exactly once); seen from above (+z) the image is upright with its x axis along +x and its
  * y axis ("down") along -y. Both sides of the plane are visible.
  */
class TablePlane : public Shape
{
public:
  using Ptr = std::shared_ptr<TablePlane>;
  using ConstPtr = std::shared_ptr<const TablePlane>;

  /** \brief An infinite table with one texture copy per tile_x x tile_y metres. */
  TablePlane (double tile_x, double tile_y);

  /** \brief Size of the area one texture copy covers, in metres (both must be positive). */
  void
  setTileSize (double tile_x, double tile_y);
  const Eigen::Vector2d&
  getTileSize () const
  {
    return tile_size_;
  }

  /** \brief Extent of the table along x and y, in metres; 0 (the default) for an infinite
    * plane along that axis.
    */
  void
  setExtent (double size_x, double size_y);
  const Eigen::Vector2d&
  getExtent () const
  {
    return extent_;
  }

  /** \brief The texture (converted with toTexture()). */
  void
  setTexture (const cv::Mat& texture);
  const cv::Mat&
  getTexture () const
  {
    return texture_;
  }

  std::string
  getTypeName () const override
  {
    return "table_plane";
  }

  bool
  validate (std::string& problem) const override;

  double
  getBoundingRadius () const override;

  bool
  intersect (const Eigen::Vector3d& origin,
             const Eigen::Vector3d& direction,
             double t_max,
             SurfaceHit& hit) const override;

  cv::Vec3f
  getColor (const SurfaceHit& hit) const override;

  /** \brief Height above the plane (negative below); off a finite rectangle, the distance to
    * the rectangle signed by the side.
    */
  double
  signedDistance (const Eigen::Vector3d& point) const override;

  std::vector<std::pair<std::string, double>>
  getDimensions () const override;

private:
  Eigen::Vector2d tile_size_;
  Eigen::Vector2d extent_ = Eigen::Vector2d::Zero();
  cv::Mat texture_;
};

} // namespace simulation
} // namespace mid
