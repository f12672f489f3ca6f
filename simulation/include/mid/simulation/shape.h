#pragma once

#include <Eigen/Core>
#include <opencv2/core/mat.hpp>

#include <memory>
#include <string>
#include <utility>
#include <vector>

namespace mid {
namespace simulation {

/** \brief Where a ray meets a shape, in the shape's model frame. */
struct SurfaceHit
{
  /** \brief Ray parameter of the hit: the point is origin + t * direction. */
  double t = 0.0;
  /** \brief Unit surface normal at the hit, facing the ray's origin, in the model frame. */
  Eigen::Vector3d normal = Eigen::Vector3d::Zero();
  /** \brief Which textured face was hit (numbering of the shape, e.g. BoxShape::Face). */
  int face = 0;
  /** \brief Texture coordinates (s, t) of the hit on that face, see sampleBilinear(). */
  Eigen::Vector2d uv = Eigen::Vector2d::Zero();
};

/** \brief The global symmetries of a shape: the rotations about its model origin that map the
  * solid onto itself, texture not considered (a gripper that holds the shape cannot tell them
  * apart; the print can). The ground truth's models_info.json lists them as BOP does
  * (formatBopModelsInfo()), so that an evaluation can score poses modulo the shape.
  */
struct ShapeSymmetries
{
  /** \brief Every rotation of the shape's finite symmetry group but the identity (for a box of
    * three different sizes the three half turns about its axes).
    */
  std::vector<Eigen::Matrix3d> discrete;
  /** \brief Unit axes through the model origin about which every turn maps the shape onto
    * itself (a cylinder's axis); with them, the symmetries are every product of a discrete one
    * and a turn about these axes.
    */
  std::vector<Eigen::Vector3d> continuous_axes;
};

/** \brief A textured solid or surface that the SceneRenderer can ray-cast: the interface every
  * primitive (box, cylinder, table plane, ...) implements.
  *
  * A shape lives in its own model frame (metres); a scene places it with a rigid pose. Shapes
  * are immutable while rendering and may be shared by several scene objects: identical
  * instances of one object share one shape.
  */
class Shape
{
public:
  using Ptr = std::shared_ptr<Shape>;
  using ConstPtr = std::shared_ptr<const Shape>;

  virtual ~Shape() = default;

  /** \brief The kind of primitive, e.g. "box" or "cylinder". */
  virtual std::string
  getTypeName () const = 0;

  /** \brief Name of the object this shape models (e.g. "juice_carton"), written to the ground
    * truth; instances sharing a shape share the name. Default: empty (the type name is used).
    */
  void
  setName (const std::string& name)
  {
    name_ = name;
  }
  const std::string&
  getName () const
  {
    return name_;
  }

  /** \brief Check the parameters and textures.
    * \param[out] problem what is wrong, empty when the shape can be rendered
    * \return true if the shape can be rendered
    */
  virtual bool
  validate (std::string& problem) const = 0;

  /** \brief Radius of a sphere about the model origin that contains the shape (used to skip
    * rays early); infinity for unbounded shapes.
    */
  virtual double
  getBoundingRadius () const = 0;

  /** \brief First intersection of a ray with the surface, seen from outside.
    * \param[in] origin ray origin in the model frame
    * \param[in] direction ray direction in the model frame (need not be unit length)
    * \param[in] t_max only hits with 0 < t < t_max count
    * \param[out] hit the hit; unspecified when false is returned
    * \return true if the ray hits the surface within (0, t_max)
    */
  virtual bool
  intersect (const Eigen::Vector3d& origin,
             const Eigen::Vector3d& direction,
             double t_max,
             SurfaceHit& hit) const = 0;

  /** \brief Surface colour (BGR, channels in [0, 255], before shading) at a hit. */
  virtual cv::Vec3f
  getColor (const SurfaceHit& hit) const = 0;

  /** \brief Signed distance of a model-frame point to the surface: negative inside a solid,
    * positive outside (for a plane: positive on the side its normal points to).
    */
  virtual double
  signedDistance (const Eigen::Vector3d& point) const = 0;

  /** \brief The size parameters as (name, metres) pairs, e.g. {"size_x", 0.07}, for the ground
    * truth.
    */
  virtual std::vector<std::pair<std::string, double>>
  getDimensions () const = 0;

  /** \brief The shape's global symmetries (see ShapeSymmetries). Default: none, as for a
    * surface that is no object (a table plane).
    */
  virtual ShapeSymmetries
  getSymmetries () const
  {
    return {};
  }

protected:
  Shape() = default;
  Shape (const Shape&) = default;
  Shape&
  operator= (const Shape&) = default;

private:
  std::string name_;
};

} // namespace simulation
} // namespace mid
