#pragma once

#include <Eigen/Core>

#include <map>
#include <string>

namespace mid {
namespace evaluation {

/** \brief The size of each object type's bounding box (edges ascending, metres), by BOP
  * obj_id, read from BOP's models_info.json ("size_x", "size_y", "size_z", millimetres).
  */
using ObjectSizeTable = std::map<int, Eigen::Vector3d>;

/** \brief Read the box size of every object of a BOP models_info.json (keyed by obj_id); an
  * object without "size_x", "size_y" and "size_z" gets no entry.
  * \param[in] path the models_info.json file
  * \param[out] table the sizes, by obj_id; cleared on failure
  * \return false (with a PCL_ERROR naming the file and the problem) if the file cannot be read,
  * is not JSON, a key is no obj_id, or an object gives some of the three edges but not all, or
  * one that is not a positive number
  */
bool
loadBopModelSizes (const std::string& path, ObjectSizeTable& table);

/** \brief How far a measured box is from the true one: the largest difference between their
  * edges, each sorted ascending (a box's edges say nothing of which is its x).
  * \param[in] measured the measured edges (metres, any order)
  * \param[in] truth the true edges (metres, any order)
  * \return the largest edge difference, millimetres
  */
double
boxSizeErrorMm (const Eigen::Vector3d& measured, const Eigen::Vector3d& truth);

} // namespace evaluation
} // namespace mid
