#pragma once

#include <mid/simulation/shape.h>

#include <array>

namespace mid {
namespace simulation {

/** \brief A box centred at its model origin, its edges along the model axes, with one texture
  * stretched over each face (true metric scale: a face of 0.07 x 0.2 m shows its whole texture
  * on 0.07 x 0.2 m, whatever the image size).
  *
  * Each texture is seen upright and unmirrored from outside the face. "Up" is +z on the four
  * side faces; their image x axis ("right") runs along:
  *  - POS_X: +y,  NEG_X: -y,  POS_Y: -x,  NEG_Y: +x (so NEG_Y is the "front" seen by a camera
  *    looking along +y with z up);
  *  - POS_Z (top): right +x, image down -y;  NEG_Z (bottom): right +x, image down +y.
  *
  * \code
  * auto carton = std::make_shared<mid::simulation::BoxShape> (0.07, 0.07, 0.2);
  * carton->setTexture (mid::simulation::makeUniformTexture ({255, 255, 255}));
  * carton->setFaceTexture (mid::simulation::BoxShape::NEG_Y, front_image);
  * \endcode
  */
class BoxShape : public Shape
{
public:
  using Ptr = std::shared_ptr<BoxShape>;
  using ConstPtr = std::shared_ptr<const BoxShape>;

  /** \brief The faces, named by their outward normal. */
  enum Face { POS_X = 0, NEG_X = 1, POS_Y = 2, NEG_Y = 3, POS_Z = 4, NEG_Z = 5 };
  /** \brief Number of faces. */
  static constexpr int FACE_COUNT = 6;

  /** \brief A box of the given edge lengths (metres), without textures yet. */
  BoxShape (double size_x, double size_y, double size_z);

  /** \brief Edge lengths along the model x, y and z axes, in metres (all must be positive). */
  void
  setSize (const Eigen::Vector3d& size)
  {
    size_ = size;
  }
  const Eigen::Vector3d&
  getSize () const
  {
    return size_;
  }

  /** \brief Texture of one face (converted with toTexture()). */
  void
  setFaceTexture (Face face, const cv::Mat& texture);
  const cv::Mat&
  getFaceTexture (Face face) const
  {
    return textures_[face];
  }

  /** \brief The same texture on all six faces. */
  void
  setTexture (const cv::Mat& texture);

  std::string
  getTypeName () const override
  {
    return "box";
  }

  bool
  validate (std::string& problem) const override;

  double
  getBoundingRadius () const override
  {
    return 0.5 * size_.norm();
  }

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

  /** \brief The rotations that permute the box's axes (with signs) onto axes of the same size:
    * the three half turns, and quarter turns about an axis across which two sizes are equal.
    */
  ShapeSymmetries
  getSymmetries () const override;

private:
  Eigen::Vector3d size_;
  std::array<cv::Mat, FACE_COUNT> textures_;
};

} // namespace simulation
} // namespace mid
