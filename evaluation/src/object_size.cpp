#include "json_file.h"

#include <mid/evaluation/object_size.h>

#include <nlohmann/json.hpp>
#include <pcl/console/print.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace mid {
namespace evaluation {

namespace {

/** Edges in ascending order. */
Eigen::Vector3d
ascending (Eigen::Vector3d edges)
{
  std::sort (edges.data(), edges.data() + 3);
  return edges;
}

} // namespace

bool
loadBopModelSizes (const std::string& path, ObjectSizeTable& table)
{
  table.clear();
  nlohmann::json models;
  if (!detail::readJsonFile (path, "mid::evaluation::loadBopModelSizes", models))
    return false;
  try {
    if (!models.is_object())
      throw std::runtime_error ("not an object keyed by obj_id");
    for (const auto& [key, model] : models.items()) {
      std::size_t used = 0;
      const int id = std::stoi (key, &used);
      if (used != key.size())
        throw std::runtime_error ("key '" + key + "' is no obj_id");
      if (!model.contains ("size_x") && !model.contains ("size_y") &&
          !model.contains ("size_z"))
        continue;
      const Eigen::Vector3d size (model.at ("size_x").get<double>(),
                                  model.at ("size_y").get<double>(),
                                  model.at ("size_z").get<double>());
      if (!size.allFinite() || !(size.minCoeff() > 0.0))
        throw std::runtime_error ("object " + key + " has no positive size");
      table[id] = ascending (0.001 * size);
    }
  }
  catch (const std::exception& error) {
    PCL_ERROR (
        "[mid::evaluation::loadBopModelSizes] '%s': %s\n", path.c_str(), error.what());
    table.clear();
    return false;
  }
  return true;
}

double
boxSizeErrorMm (const Eigen::Vector3d& measured, const Eigen::Vector3d& truth)
{
  return 1000.0 * (ascending (measured) - ascending (truth)).cwiseAbs().maxCoeff();
}

} // namespace evaluation
} // namespace mid
