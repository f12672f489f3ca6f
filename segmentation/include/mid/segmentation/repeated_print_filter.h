#pragma once

#include <mid/registration/object_model.h>
#include <mid/segmentation/support_plane_measurement.h>

#include <cstddef>
#include <string>

namespace mid {

/** \brief Removes the instances of a model that lie on the same physical object as another of
  * its instances, shifted along a print that repeats on it (not in the paper).
  *
  * A print that repeats on one carton (a logo twice on a face, lines of small text, a band
  * around it) can give a model whose instances are the repeats: its clusters pass every
  * check of the triplets and of the look, since the surface around each repeat is the same.
  * Such a model counts as an object, and in a frame whose product has a true model it even
  * counts as its second one. removeOverlappingInstances() takes the repeats whose keypoints
  * intermix; this step takes those shifted farther than their own extent, by the object they
  * lie on. For each instance, the ones observing more keypoints first (the one kept of a
  * repeating pair is the one with more keypoints, whichever of the two is shifted):
  *
  * 1. the instances after it whose poses turn the model by less than `max_rotation` against
  *    its pose (posesCoincide()) are the candidates: a print that repeats on one face is not
  *    turned;
  * 2. if there are any, the surface grown from its keypoints alone (growInstanceSurfaces(),
  *    stopped at creases and depth steps, off the support plane) gives the box of the object
  *    it lies on (fitInstanceBox());
  * 3. a candidate repeats it, and is removed, when at least `min_inside_share` of its
  *    keypoints lie in that box (within 5 mm) and its pose moves the model's landmarks (their
  *    centroid) by less than both `max_shift_ratio` times the box's shortest edge and
  *    `max_shift_along_width` times the box's width along the shift.
  *
  * The two shift bounds keep copies that touch without a crease between them, which the box
  * spans as one object. Two copies that do not interpenetrate lie at least their width along
  * the shift apart, so n copies in a flush row lie 1/n of the box's width along the row apart:
  * rows of up to four keep their copies by the second bound (default 0.25); the first keeps
  * longer rows, whose box is no thicker than one copy, unless the copies are thinner along the
  * row than 0.75 of their other edges (five or more thin copies standing flush like books are
  * taken for repeats). The repeats of prints on the benchmark's cartons lie 0.34 to 0.50
  * shortest edges and 0.06 to 0.14 widths apart.
  *
  * A model that this leaves with one instance is removed with it (that instance counts as
  * removed). Frames without a support plane (none holding kMinSupportPlaneShare of the points)
  * are left as they are. Deterministic.
  */
class RepeatedPrintFilter : public SupportPlaneMeasurement
{
public:
  /** \brief Largest rotation between two instances on one object (radians, default 15 deg,
    * in [0, pi]).
    */
  ///@{
  void
  setMaxRotation (float angle)
  {
    max_rotation_ = angle;
  }
  float
  getMaxRotation () const
  {
    return max_rotation_;
  }
  ///@}

  /** \brief Largest shift between two instances on one object, as a share of the shortest
    * edge of the object's box (default 0.75, >= 0).
    */
  ///@{
  void
  setMaxShiftRatio (float ratio)
  {
    max_shift_ratio_ = ratio;
  }
  float
  getMaxShiftRatio () const
  {
    return max_shift_ratio_;
  }
  ///@}

  /** \brief Largest shift between two instances on one object, as a share of the object box's
    * width along the shift (default 0.25, >= 0).
    */
  ///@{
  void
  setMaxShiftAlongWidth (float ratio)
  {
    max_shift_along_width_ = ratio;
  }
  float
  getMaxShiftAlongWidth () const
  {
    return max_shift_along_width_;
  }
  ///@}

  /** \brief Smallest share of an instance's keypoints that must lie in the other's object box (default
    * 0.8, in [0, 1]).
    */
  ///@{
  void
  setMinInsideShare (float share)
  {
    min_inside_share_ = share;
  }
  float
  getMinInsideShare () const
  {
    return min_inside_share_;
  }
  ///@}

  /** \brief Remove the repeats from `models`.
    * \param[in,out] models the models (their instances' keypoints index the input keypoints);
    * the remaining instances keep their order
    * \param[out] removed the number of instances removed (repeats, and the last instance of a
    * model of repeats alone)
    * \return false (with a PCL_ERROR naming the problem, the models untouched, removed 0) if
    * an input or a parameter is unusable
    */
  bool
  filter (ObjectModels& models, std::size_t& removed) const;

private:
  /** \brief What is wrong with the inputs or the parameters; empty if nothing. */
  std::string
  inputProblem (const ObjectModels& models) const;

  float max_rotation_ = 0.2617994f;     ///< see setMaxRotation() (15 deg)
  float max_shift_ratio_ = 0.75f;       ///< see setMaxShiftRatio()
  float max_shift_along_width_ = 0.25f; ///< see setMaxShiftAlongWidth()
  float min_inside_share_ = 0.8f;       ///< see setMinInsideShare()
};

} // namespace mid
