#include <mid/segmentation/consensus_boxes.h>
#include <mid/segmentation/instance_extent.h>

#include <Eigen/Geometry>
#include <pcl/console/print.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>

namespace mid {

namespace {

using Points = std::vector<Eigen::Vector3f>;

/** Every how many rows and columns a surface's pixels are compared: a quarter of them costs a
  * sixteenth of the comparisons, and the box fitted to them still reaches within a pixel of
  * the edges.
  */
constexpr std::uint32_t kConsensusStride = 2;

bool
onStride (pcl::index_t pixel, std::uint32_t width)
{
  const auto index = static_cast<std::uint32_t> (pixel);
  return (index / width) % kConsensusStride == 0 &&
         (index % width) % kConsensusStride == 0;
}

/** The copies' surface points in the model frame, hashed into cubes of one edge, each cube's
  * points kept copy by copy: a point's neighbours within that edge lie in its own cube or the
  * 26 around it, and a copy's points in a cube are skipped at once when they do not count.
  */
class CopyGrid
{
public:
  explicit CopyGrid (float cell) : cell_ (cell) {}

  /** \brief Add point p of copy `copy`. */
  void
  add (const Eigen::Vector3f& p, std::size_t copy)
  {
    std::vector<CopyPoints>& cell = cells_[key (cellOf (p))];
    const auto found =
        std::find_if (cell.begin(), cell.end(), [copy] (const CopyPoints& c) {
          return c.copy == copy;
        });
    if (found == cell.end())
      cell.push_back ({copy, {p}});
    else
      found->points.push_back (p);
  }

  /** \brief True if a point of a copy other than `copy` lies within the cell edge of p. */
  bool
  nearOtherCopy (const Eigen::Vector3f& p, std::size_t copy) const
  {
    return nearAny (p, [copy] (std::size_t c) { return c != copy; });
  }

  /** \brief True if a point of copy `copy` lies within the cell edge of p. */
  bool
  nearCopy (const Eigen::Vector3f& p, std::size_t copy) const
  {
    return nearAny (p, [copy] (std::size_t c) { return c == copy; });
  }

private:
  struct CopyPoints
  {
    std::size_t copy;
    Points points;
  };

  /** True if a point of a copy that `counts` lies within the cell edge of p. */
  template <typename Counts>
  bool
  nearAny (const Eigen::Vector3f& p, const Counts& counts) const
  {
    const Eigen::Vector3i c = cellOf (p);
    const float squared = cell_ * cell_;
    for (int dx = -1; dx <= 1; ++dx)
      for (int dy = -1; dy <= 1; ++dy)
        for (int dz = -1; dz <= 1; ++dz) {
          const auto found = cells_.find (key (c + Eigen::Vector3i (dx, dy, dz)));
          if (found == cells_.end())
            continue;
          for (const auto& group : found->second)
            if (counts (group.copy))
              for (const auto& q : group.points)
                if ((q - p).squaredNorm() <= squared)
                  return true;
        }
    return false;
  }

  /** The cube of p; coordinates clamped to +-2^30 cubes, so that the cast is defined for every
    * finite point (cubes that far apart only share keys, and the distance test tells them
    * apart).
    */
  Eigen::Vector3i
  cellOf (const Eigen::Vector3f& p) const
  {
    constexpr float kFarthest = 1073741824.0f;
    return (p / cell_).array().floor().max (-kFarthest).min (kFarthest).cast<int>();
  }

  /** 21 bits per coordinate: cells of a millimetre reach a kilometre. */
  static std::int64_t
  key (const Eigen::Vector3i& c)
  {
    constexpr std::int64_t kMask = (std::int64_t{1} << 21) - 1;
    return ((static_cast<std::int64_t> (c.x()) & kMask) << 42) |
           ((static_cast<std::int64_t> (c.y()) & kMask) << 21) |
           (static_cast<std::int64_t> (c.z()) & kMask);
  }

  float cell_;
  std::unordered_map<std::int64_t, std::vector<CopyPoints>> cells_;
};

} // namespace

bool
consensusBoxes (const pcl::PointCloud<pcl::PointXYZ>& organized,
                const Eigen::Vector4f& plane,
                const ObjectModel& model,
                const InstanceExtents& extents,
                float radius,
                InstanceExtents& consensus)
{
  consensus.clear();
  if (extents.size() != model.instances.size()) {
    PCL_ERROR ("[mid::consensusBoxes] %zu boxes for %zu instances.\n",
               extents.size(),
               model.instances.size());
    return false;
  }
  if (!(radius > 0.0f) || !std::isfinite (radius)) {
    PCL_ERROR ("[mid::consensusBoxes] The radius must be finite and > 0, not %g.\n",
               static_cast<double> (radius));
    return false;
  }
  for (const auto& extent : extents)
    if (const char* problem = surfacePixelsProblem (organized, extent.surface)) {
      PCL_ERROR ("[mid::consensusBoxes] %s.\n", problem);
      return false;
    }
  consensus.assign (extents.size(), InstanceExtent());
  if (measuredInstances (extents).size() < 2)
    return true;

  // Every copy's surface (every kConsensusStride-th row and column) in the model frame:
  // x_model = pose^-1 * x_camera.
  std::vector<pcl::Indices> pixels (extents.size());
  std::vector<Points> in_model (extents.size());
  CopyGrid grid (radius);
  for (std::size_t i = 0; i < extents.size(); ++i) {
    const Eigen::Affine3f to_model (model.instances[i].pose.inverse());
    for (const auto pixel : extents[i].surface)
      if (onStride (pixel, organized.width)) {
        pixels[i].push_back (pixel);
        in_model[i].push_back (to_model * organized[pixel].getVector3fMap());
        grid.add (in_model[i].back(), i);
      }
  }
  // A pixel lies near another copy's surface, or not; the ones that do not, in a grid of their
  // own.
  std::vector<std::vector<bool>> shared (extents.size());
  CopyGrid unshared (radius);
  for (std::size_t i = 0; i < extents.size(); ++i)
    for (const auto& p : in_model[i]) {
      shared[i].push_back (grid.nearOtherCopy (p, i));
      if (!shared[i].back())
        unshared.add (p, i);
    }
  // Kept: the shared pixels farther than the radius from the copy's unshared ones. A neighbour
  // lying flush with the copy is shared up to the radius past the other copies' edges; that
  // band goes with the rest of the neighbour, and the box ends at the copy's edge.
  for (std::size_t i = 0; i < extents.size(); ++i) {
    pcl::Indices kept;
    for (std::size_t k = 0; k < in_model[i].size(); ++k)
      if (shared[i][k] && !unshared.nearCopy (in_model[i][k], i))
        kept.push_back (pixels[i][k]);
    if (!fitInstanceBox (organized, plane, kept, consensus[i]))
      consensus[i] = InstanceExtent();
  }
  return true;
}

} // namespace mid
