#pragma once

#include <Eigen/Core>

#include <map>
#include <string>
#include <vector>

namespace mid {
namespace evaluation {

/** \brief The global symmetries of an object's shape, read from BOP's models_info.json: a pose
  * that differs from the true one by such a symmetry puts the same solid in the same place. A
  * gripper that holds the shape cannot tell them apart; the print can. Only the rotations are
  * kept: the evaluation compares rotations modulo these (symmetricRotationError()).
  */
struct ObjectSymmetries
{
  /** \brief The rotation parts of "symmetries_discrete" (each entry a 4 x 4 row-major motion). */
  std::vector<Eigen::Matrix3d> discrete;
  /** \brief The unit axes of "symmetries_continuous": every turn about one of them is a
    * symmetry too, also after a discrete one.
    */
  std::vector<Eigen::Vector3d> continuous_axes;
};

/** \brief The symmetries of each object type, by BOP obj_id; a type without an entry has none. */
using ObjectSymmetryTable = std::map<int, ObjectSymmetries>;

/** \brief Read the symmetries of every object of a BOP models_info.json (keyed by obj_id); an
  * object without "symmetries_discrete" or "symmetries_continuous" gets an empty entry.
  * \param[in] path the models_info.json file
  * \param[out] table the symmetries, by obj_id; cleared on failure
  * \return false (with a PCL_ERROR naming the file and the problem) if the file cannot be read,
  * is not JSON, a key is no obj_id, a discrete entry is not 16 numbers whose rotation part is a
  * rotation, or an axis is not a non-zero 3-vector
  */
bool
loadBopModelSymmetries (const std::string& path, ObjectSymmetryTable& table);

/** \brief The angle between an estimated and a true orientation of one object, modulo the
  * object's symmetries: the smallest angle of estimated^T * truth * S over every symmetry S
  * (the identity, each discrete one, each of those followed by any turn about a continuous
  * axis; two different continuous axes make every orientation a symmetry).
  * \param[in] estimated the estimated rotation (model to camera)
  * \param[in] truth the true rotation (model to camera)
  * \param[in] symmetries the object's symmetries; without any, the plain angle
  * \return the angle in degrees, in [0, 180]
  */
double
symmetricRotationError (const Eigen::Matrix3d& estimated,
                        const Eigen::Matrix3d& truth,
                        const ObjectSymmetries& symmetries);

} // namespace evaluation
} // namespace mid
