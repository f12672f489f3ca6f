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
  * lie on. For each pair of instances of one model, the one observing more keypoints first:
  *
  * 1. the surface grown from the first instance's keypoints alone (growInstanceSurfaces(),
  *    stopped at creases and depth steps, off the support plane) gives the box of the object
  *    it lies on (fitInstanceBox());
  * 2. the second instance is the same object when all three hold:
  *    - at least `min_inside_share` of its keypoints lie in that box (within 5 mm);
  *    - its pose turns the model by less than `max_rotation` against the first's: a print
  *      that repeats on one face is not turned;
  *    - its pose moves the model's landmarks (their centroid) by less than `max_shift_ratio`
  *      times the box's shortest edge. Two copies that do not interpenetrate lie at least
  *      their own width apart, and where two copies touch without a crease between them the
  *      box spans both: its shortest edge is then at most a copy's width or height, and the
  *      shift at least the width.
  *    and is removed.
  *
  * A model that this leaves with fewer than two instances is removed (a model without any
  * instance too). Frames without a support plane
  * (none holding kMinSupportPlaneShare of the points) are left as they are. Deterministic.
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

  /** \brief Share of an instance's keypoints that must lie in the other's object box (default
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
    * \param[out] removed the number of instances removed
    * \return false (with a PCL_ERROR naming the problem, the models untouched, removed 0) if
    * an input or a parameter is unusable
    */
  bool
  filter (ObjectModels& models, std::size_t& removed) const;

private:
  /** \brief What is wrong with the inputs or the parameters; empty if nothing. */
  std::string
  inputProblem (const ObjectModels& models) const;

  float max_rotation_ = 0.2617994f; ///< see setMaxRotation() (15 deg)
  float max_shift_ratio_ = 0.75f;   ///< see setMaxShiftRatio()
  float min_inside_share_ = 0.8f;   ///< see setMinInsideShare()
};

} // namespace mid
