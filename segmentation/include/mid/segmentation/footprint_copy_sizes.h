#pragma once

#include <mid/segmentation/footprint_split.h>

#include <Eigen/Core>
#include <Eigen/StdVector>

#include <vector>

namespace mid {

/** \brief The rectangles that two or three copies of one box of unknown size, touching each
  * other with their tops at one height, may occupy in a footprint that is no rectangle (not in
  * the paper).
  *
  * Copies of a product that show different faces have nothing to match, and copies that touch
  * are measured as one object of no model's size. When that object's footprint on the support
  * plane is a rectangle, it may as well be one box of its size (a cookie box covers two juice
  * cartons lying flush): nothing tells them apart. When it is not (it fills at most
  * `max_fill` of the smallest rectangle around it: copies side by side but shifted, one across
  * another's end, at an angle), it is no one box, and every copy at the outside of the group
  * shows whole edges on its outline, between right-angled corners. This function rasterizes
  * the footprint (cells of `cell`), simplifies its outline (by 2 cells), takes the lengths of
  * the outline's edges of at least `min_edge` whose corners at both ends are right angles
  * (within 20 deg; a disc, the footprint of a can standing, has none) for the copies'
  * possible edges, and returns the rectangles of two of them
  * whose area, two or three times, is the footprint's (within 20 %), the closest first.
  * splitFootprint() cuts the footprint by each; it is for the caller to keep a cut whose
  * parts, measured on their own, have one size.
  *
  * \param[in] points the footprint: an object's points projected onto the plane (metres)
  * \param[in] cell the raster's cell (metres, > 0)
  * \param[in] min_edge the copies' shortest edge (metres, > 0; ten cells or more, for the
  * outline to measure it)
  * \param[in] max_fill largest share of the smallest rectangle around the footprint that the
  * footprint may fill, in (0, 1]
  * \param[out] sizes the rectangles (edges, short first), each once, the closest to a share
  * of the footprint's area first; empty for a footprint that fills more than `max_fill`
  * \return false (with a PCL_ERROR, sizes empty) on a parameter out of range, a point that is
  * not finite, or a footprint of more than 4 million cells; true otherwise
  */
bool
footprintCopySizes (
    const std::vector<Eigen::Vector2f, Eigen::aligned_allocator<Eigen::Vector2f>>&
        points,
    float cell,
    float min_edge,
    float max_fill,
    std::vector<Eigen::Vector2f, Eigen::aligned_allocator<Eigen::Vector2f>>& sizes);

/** \brief Share of the smallest rectangle around `rectangles` that they fill (the sum of their
  * areas over its area; 0 if there are none): near 1 when they tile a rectangle, as the copies
  * cut from a box's footprint, or from a long prism's, along its length do. Copies that one box
  * of their union's size could not have made fill clearly less.
  */
float
rectanglesFill (const FootprintRectangles& rectangles);

} // namespace mid
