#pragma once

#include <mid/simulation/shape.h>

#include <array>

namespace mid {
namespace simulation {

/** \brief A solid cylinder centred at its model origin, its axis along model z, with a side
  * texture wrapped once around it and a texture on each cap (true metric scale: the side
  * texture covers the circumference 2 pi r times the height).
  *
  * The side texture is upright (+z up) and unmirrored from outside; its left and right edges
  * meet along the line at angle pi (the -x side), and its x axis runs with increasing
  * angle atan2 (y, x). The caps are oriented like the top and bottom faces of a BoxShape:
  * TOP (+z): right +x, image down -y; BOTTOM (-z): right +x, image down +y.
  */
class CylinderShape : public Shape
{
public:
  using Ptr = std::shared_ptr<CylinderShape>;
  using ConstPtr = std::shared_ptr<const CylinderShape>;

  /** \brief The textured faces. */
  enum Face { SIDE = 0, TOP = 1, BOTTOM = 2 };
  /** \brief Number of faces. */
  static constexpr int FACE_COUNT = 3;

  /** \brief A cylinder of the given radius and height (metres), without textures yet. */
  CylinderShape (double radius, double height);

  /** \brief Radius in metres (must be positive). */
  void
  setRadius (double radius)
  {
    radius_ = radius;
  }
  double
  getRadius () const
  {
    return radius_;
  }

  /** \brief Height along the model z axis in metres (must be positive). */
  void
  setHeight (double height)
  {
    height_ = height;
  }
  double
  getHeight () const
  {
    return height_;
  }

  /** \brief Texture of one face (converted with toTexture()). */
  void
  setFaceTexture (Face face, const cv::Mat& texture);
  const cv::Mat&
  getFaceTexture (Face face) const
  {
    return textures_[face];
  }

  /** \brief The same texture on the side and both caps. */
  void
  setTexture (const cv::Mat& texture);

  std::string
  getTypeName () const override
  {
    return "cylinder";
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

  double
  signedDistance (const Eigen::Vector3d& point) const override;

  std::vector<std::pair<std::string, double>>
  getDimensions () const override;

  /** \brief Every turn about the axis (model z), and the half turn about x that swaps the two
    * caps.
    */
  ShapeSymmetries
  getSymmetries () const override;

private:
  double radius_;
  double height_;
  std::array<cv::Mat, FACE_COUNT> textures_;
};

} // namespace simulation
} // namespace mid
