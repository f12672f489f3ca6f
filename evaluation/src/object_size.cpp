#include "json_file.h"

#include <mid/evaluation/object_size.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <stdexcept>
#include <string>

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
  const auto read = [&table] (int id, const nlohmann::json& model) {
    if (!model.contains ("size_x") && !model.contains ("size_y") &&
        !model.contains ("size_z"))
      return;
    const Eigen::Vector3d size (model.at ("size_x").get<double>(),
                                model.at ("size_y").get<double>(),
                                model.at ("size_z").get<double>());
    if (!size.allFinite() || !(size.minCoeff() > 0.0))
      throw std::runtime_error ("object " + std::to_string (id) +
                                " has no positive size");
    table[id] = ascending (0.001 * size);
  };
  if (!detail::readBopModelsInfo (path, "mid::evaluation::loadBopModelSizes", read)) {
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
