#pragma once

#include <mid/registration/object_model.h>
#include <mid/segmentation/support_plane_measurement.h>

#include <cstddef>

namespace mid {

/** \brief Removes the instances that lie flat in the support plane: prints on the table, not
  * copies resting on it (not in the paper).
  *
  * Sheets of paper with the same layout (the fiducial markers around a bin, a form), or a mat
  * whose pattern repeats, give repeated keypoints that pass every check of the triplets and of
  * the look, and a model whose instances are the sheets. A robot cannot pick them, and the
  * user asked for the objects on the table, not for the table's print. Such an instance shows
  * itself by where it lies:
  *
  * 1. at least `min_share_on_plane` of its keypoints lie within the plane tolerance
  *    (setPlaneTolerance(), default 1 cm) of the frame's support plane, while a copy resting
  *    on the table shows its keypoints on faces that stand off it;
  * 2. at least half of the pixels around its keypoints (the ring between their image box and
  *    that box grown by half its longer side, at least 10 pixels, on every side) lie on the
  *    plane too: a print lies on a surface that goes on around it, while the top of an object
  *    to which the plane was fitted (a frame without a table in view) ends at its edges.
  *
  * And the plane must be seen to support the objects found: an instance stands off it towards
  * the camera (its median keypoint more than the tolerance in front) and none lies beyond it
  * (its median keypoint more than the tolerance behind). A plane fitted to a layer of tops
  * seen from above, with nothing on it, or to a surface with found objects behind it, is not
  * the table: nothing is removed then.
  *
  * On the IC-BIN frames, 96 to 100 % of the keypoints of the models of marker sheets and sheet
  * edges lie within 1 cm of the table, and none of those of the juice cartons and coffee cups.
  * A model that this leaves with one instance is removed with it (that instance counts as
  * removed). Objects thinner than the plane tolerance lying on the table (cards, stickers,
  * coins) are prints to this step: turn it off, or lower the tolerance, for those. Frames
  * without a support plane (none holding kMinSupportPlaneShare of the points) are left as
  * they are. No surface is grown: the growth settings of SupportPlaneMeasurement
  * (setMaxStep(), setMaxRadius()) are not read. Deterministic.
  */
class SupportPrintFilter : public SupportPlaneMeasurement
{
public:
  /** \brief Smallest share of an instance's keypoints within the plane tolerance of the
    * support plane for the instance to be a print on it (default 0.8, in (0, 1]).
    */
  ///@{
  void
  setMinShareOnPlane (float share)
  {
    min_share_on_plane_ = share;
  }
  float
  getMinShareOnPlane () const
  {
    return min_share_on_plane_;
  }
  ///@}

  /** \brief Remove the instances that lie flat in the support plane from `models`.
    * \param[in,out] models the models (their instances' keypoints index the input keypoints);
    * the remaining instances keep their order
    * \param[out] removed the number of instances removed (with the last instance of a model
    * left with one)
    * \return false (with a PCL_ERROR naming the problem, the models untouched, removed 0) if
    * an input or a parameter is unusable
    */
  bool
  filter (ObjectModels& models, std::size_t& removed) const;

private:
  float min_share_on_plane_ = 0.8f; ///< see setMinShareOnPlane()
};

} // namespace mid
