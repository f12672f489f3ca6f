#pragma once

#include "free_objects.h"

#include <mid/features/keypoint_types.h>
#include <mid/segmentation/model_size.h>

#include <Eigen/Core>
#include <pcl/point_cloud.h>
#include <pcl/point_types.h>

namespace mid {
namespace detail {

/** \brief Cuts an object on the table (a FreeObject of SizeInstanceSearch) into the copies of
  * one box it holds: copies touching each other flush with their tops at one height (by the
  * rectangles of a known box, or by the edges of the object's outline), copies joined with
  * each other (by their flat tops), or one copy joined with something else (by its flat top).
  * Each copy comes with its pixels, its keypoints and its box measured on its own
  * (fitInstanceBox()).
  *
  * The frame (cloud, support plane, keypoints and their pixels) must outlive the cutter.
  */
class CopyCutter
{
public:
  /** \param[in] organized the organized frame (camera frame, metres)
    * \param[in] plane the support plane
    * \param[in] keypoints the frame's keypoints
    * \param[in] keypoint_pixels each keypoint's pixel in `organized`
    * \param[in] agree when two sizes are one
    * \param[in] min_keypoints fewest keypoints of a copy, where a cut asks for them
    * \param[in] min_edge shortest edge of a copy of a box of unknown size (metres)
    */
  CopyCutter (const pcl::PointCloud<pcl::PointXYZ>& organized,
              const Eigen::Vector4f& plane,
              const KeypointCloud& keypoints,
              const pcl::Indices& keypoint_pixels,
              const SizeAgreement& agree,
              int min_keypoints,
              float min_edge)
  : organized_ (organized)
  , plane_ (plane)
  , keypoints_ (keypoints)
  , keypoint_pixels_ (keypoint_pixels)
  , agree_ (agree)
  , min_keypoints_ (min_keypoints)
  , min_edge_ (min_edge)
  {}

  /** \brief The parts of `object` that copies of a box of `size` (a model's), touching each
    * other flush with their tops at one height, occupy (splitFootprint()): its pixels and
    * keypoints nearest each copy's rectangle on the plane, with the box fitted to them, so
    * that a copy is measured on its own outline, not on the rectangle. None if the object's
    * height is none of the box's edges or its footprint is not such a group. The parts' own
    * sizes and keypoints are not checked.
    */
  FreeObjects
  flushCopies (const FreeObject& object, const Eigen::Vector3f& size) const;

  /** \brief The parts of `object`, of no model's size, that two or three copies of one box of
    * unknown size occupy, touching each other with their tops at one height, when its
    * footprint is no rectangle and something in front hides little of its outline: cut by
    * each rectangle that the edges of its outline give (footprintCopySizes()), the object's
    * height the box's third edge (flushCopies()), the first cut into parts that each hold
    * `min_keypoints`, have no edge shorter than `min_edge` (2 cm at least: the raster's cells
    * measure a tenth of an edge, 4 mm at most), agree in size with the first part
    * and, at twice the tolerances (the outline's edges are a raster's), with the box, and
    * whose boxes leave room in the rectangle around them on the plane (a long prism cut
    * along its length fills it). None if no cut does.
    */
  FreeObjects
  copiesOfItsOutline (const FreeObject& object) const;

  /** \brief The copy of a box of `size` that `object` holds, joined with something else,
    * found by its flat top (flatTopParts()): the first part under a top, of `min_keypoints`
    * but not all of the object's, whose box has that size. None otherwise.
    */
  FreeObjects
  copyByItsFlatTop (const FreeObject& object, const Eigen::Vector3f& size) const;

  /** \brief Two or more copies of one box of unknown size that `object`, of no model's size,
    * holds, joined with each other (one standing, one lying, or at right angles) and none seen
    * alone: for each box that a flat top of the object suggests (flatTopSizes()), no edge
    * shorter than `min_edge`, its parts under the tops (a part holding no keypoint that an
    * earlier one does not is the same top again) with no edge shorter than `min_edge` that
    * agree in size with the first of them and, at twice the tolerances (a suggestion is a
    * level patch's rectangle, not a measured box), with the suggestion. A keypoint two parts
    * hold (where the copies touch) is neither's; the first suggestion that leaves two parts
    * of `min_keypoints` gives the copies. None otherwise.
    */
  FreeObjects
  copiesOfItsFlatTops (const FreeObject& object) const;

  /** \brief The copy of a box of `size` that `object` is, hidden in part by something in
    * front (completeHiddenCopy()): the object with its box completed beyond the hidden end.
    * None otherwise.
    */
  FreeObjects
  hiddenCopy (const FreeObject& object, const Eigen::Vector3f& size) const;

  /** \brief True if `a` and `b` may be the two ends of one box that something in front hides
    * in the middle (endsOfOneHiddenBox()): one object seen twice, not two copies.
    */
  bool
  endsOfOneBox (const FreeObject& a, const FreeObject& b) const;

private:
  /** \brief The parts of `object` under the flat tops of a box of `size` (flatTopParts()),
    * each with the object's keypoints whose pixel it holds: those with at least
    * `min_keypoints` of them, not all, whose box could be measured.
    */
  FreeObjects
  flatTopCopies (const FreeObject& object, const Eigen::Vector3f& size) const;

  const pcl::PointCloud<pcl::PointXYZ>& organized_;
  Eigen::Vector4f plane_;
  const KeypointCloud& keypoints_;
  const pcl::Indices& keypoint_pixels_;
  SizeAgreement agree_;
  int min_keypoints_;
  float min_edge_;

public:
  EIGEN_MAKE_ALIGNED_OPERATOR_NEW
};

} // namespace detail
} // namespace mid
