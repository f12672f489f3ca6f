#include "json_file.h"

#include <mid/evaluation/object_symmetry.h>

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace mid {
namespace evaluation {

namespace {

using nlohmann::json;

/** Angle (degrees) of a rotation whose trace is given. */
double
angleOfTrace (double trace)
{
  return std::acos (std::clamp ((trace - 1.0) / 2.0, -1.0, 1.0)) * 180.0 / M_PI;
}

/** The smallest angle of m * R(axis, theta) over theta, in degrees. With R = cos I + sin [a]x +
  * (1 - cos) a a^T, trace(m R) = a^T m a + cos (tr m - a^T m a) + sin tr(m [a]x), whose
  * largest value over theta is a^T m a + the norm of the two coefficients.
  */
double
smallestAngleAbout (const Eigen::Matrix3d& m, const Eigen::Vector3d& axis)
{
  Eigen::Matrix3d cross;
  cross << 0.0, -axis.z(), axis.y(), axis.z(), 0.0, -axis.x(), -axis.y(), axis.x(), 0.0;
  const double along = axis.dot (m * axis);
  const double a = m.trace() - along, b = (m * cross).trace();
  return angleOfTrace (along + std::hypot (a, b));
}

ObjectSymmetries
symmetriesOf (const json& model)
{
  ObjectSymmetries symmetries;
  for (const auto& entry : model.value ("symmetries_discrete", json::array())) {
    const auto values = entry.get<std::vector<double>>();
    if (values.size() != 16)
      throw std::runtime_error ("a discrete symmetry needs 16 numbers");
    const Eigen::Matrix3d rotation =
        Eigen::Map<const Eigen::Matrix<double, 4, 4, Eigen::RowMajor>> (values.data())
            .topLeftCorner<3, 3>();
    if (!rotation.allFinite() || !rotation.isUnitary (1e-6) ||
        rotation.determinant() <= 0.0)
      throw std::runtime_error ("a discrete symmetry's rotation part is no rotation");
    symmetries.discrete.push_back (rotation);
  }
  for (const auto& entry : model.value ("symmetries_continuous", json::array())) {
    const auto axis = entry.at ("axis").get<std::vector<double>>();
    if (axis.size() != 3)
      throw std::runtime_error ("a continuous symmetry's axis needs 3 numbers");
    const Eigen::Vector3d unit (axis[0], axis[1], axis[2]);
    if (!unit.allFinite() || unit.norm() < 1e-9)
      throw std::runtime_error ("a continuous symmetry's axis is zero");
    symmetries.continuous_axes.push_back (unit.normalized());
  }
  return symmetries;
}

} // namespace

bool
loadBopModelSymmetries (const std::string& path, ObjectSymmetryTable& table)
{
  table.clear();
  if (!detail::readBopModelsInfo (
          path,
          "mid::evaluation::loadBopModelSymmetries",
          [&table] (int id, const json& model) { table[id] = symmetriesOf (model); })) {
    table.clear();
    return false;
  }
  return true;
}

double
symmetricRotationError (const Eigen::Matrix3d& estimated,
                        const Eigen::Matrix3d& truth,
                        const ObjectSymmetries& symmetries)
{
  const auto& axes = symmetries.continuous_axes;
  for (std::size_t i = 1; i < axes.size(); ++i)
    if (axes[i].cross (axes[0]).norm() > 1e-6)
      return 0.0;
  const Eigen::Matrix3d m = estimated.transpose() * truth;
  const auto angle = [&axes] (const Eigen::Matrix3d& r) {
    return axes.empty() ? angleOfTrace (r.trace()) : smallestAngleAbout (r, axes[0]);
  };
  double smallest = angle (m);
  for (const Eigen::Matrix3d& symmetry : symmetries.discrete)
    smallest = std::min (smallest, angle (m * symmetry));
  return smallest;
}

} // namespace evaluation
} // namespace mid
