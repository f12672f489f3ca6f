#pragma once

#include <Eigen/Core>
#include <Eigen/StdVector>

#include <vector>

namespace mid {

/** \brief A rectangle on the support plane, in the plane's 2D coordinates (metres). */
struct FootprintRectangle
{
  /** \brief Its centre. */
  Eigen::Vector2f centre = Eigen::Vector2f::Zero();
  /** \brief Unit direction of its first edge; the second is this turned by 90 deg. */
  Eigen::Vector2f direction = Eigen::Vector2f::UnitX();
  /** \brief Its edges: along `direction`, and across it. */
  Eigen::Vector2f size = Eigen::Vector2f::Zero();

  /** \brief True if `point` lies inside, or within `margin` of it. */
  bool
  holds (const Eigen::Vector2f& point, float margin) const;

  /** \brief How far `point` lies outside (0 inside). */
  float
  distance (const Eigen::Vector2f& point) const;

  EIGEN_MAKE_ALIGNED_OPERATOR_NEW
};

/** \brief Rectangles on the support plane (splitFootprint()). */
using FootprintRectangles =
    std::vector<FootprintRectangle, Eigen::aligned_allocator<FootprintRectangle>>;

/** \brief Cut the footprint of copies of one box that touch each other flush into the
  * rectangles they occupy (not in the paper).
  *
  * Copies lying side by side or end to end with their tops at one height form one surface:
  * no crease or depth step tells where one ends. Their footprint on the support plane is a
  * union of rectangles of the copies' size, and every copy at the outside of the group shows
  * a corner on its outline. This function rasterizes the footprint (cells of `cell`) and
  * counts how many copies its area holds (a copy's rectangle plus the raster's border), then
  * places the rectangle of `size` at a right-angled corner of the outline of what is left
  * (its convex hull, simplified), along either edge and either way round, the placement whose
  * cells the footprint covers best (at least `min_coverage`) first, and takes its cells away,
  * until none fits. The first placement is tried every way that fits, and the rectangles kept
  * are those of the way that places as many as the area holds copies and covers most of the
  * footprint (80 % at least). Boxes of another size whose footprint the rectangles happen to
  * tile that way are taken for copies: the caller measures each part on its own outline.
  *
  * \param[in] points the footprint: the object's points projected onto the plane (metres)
  * \param[in] size the copies' rectangle (edges, metres, > 0)
  * \param[in] cell the raster's cell (metres, > 0; a tenth of the shortest edge or less)
  * \param[in] min_coverage share of a placed rectangle's cells that the footprint must cover
  * (in (0, 1])
  * \param[out] rectangles the copies' rectangles, at least two; empty when the footprint is
  * not a group of 2 to 32 copies (less than 1.6 copies' area or more than 32, or no placement
  * as above)
  * \return false (with a PCL_ERROR, rectangles empty) on a size, cell or coverage out of range
  * (the cell more than a tenth of the shortest edge), a point that is not finite, or a
  * footprint of more than 4 million cells; true otherwise, also when nothing is cut
  */
bool
splitFootprint (const std::vector<Eigen::Vector2f,
                                  Eigen::aligned_allocator<Eigen::Vector2f>>& points,
                const Eigen::Vector2f& size,
                float cell,
                float min_coverage,
                FootprintRectangles& rectangles);

} // namespace mid
