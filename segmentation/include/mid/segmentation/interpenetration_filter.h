#pragma once

#include <mid/registration/object_model.h>
#include <mid/segmentation/model_size.h>

#include <string>

namespace mid {

/** \brief Removes the instances of a model whose boxes would interpenetrate the box of another
  * of its instances (not in the paper).
  *
  * Copies of one object cannot occupy one place. A box with shortest edge e holds a sphere of
  * diameter e around its centre, so two copies whose boxes' centres lie closer than e
  * interpenetrate. Two instances of a model that do so lie on one physical copy: one of them
  * has a wrong pose (a quarter turn of a square carton found once by its print and once by its
  * box, a partial match), and it is counted as a copy that is not there. For each model whose
  * copies agree on a size (measureModelSizes(), the size merge's rule), the instances that
  * observe more keypoints go first (ties: the earlier), and every later instance whose box
  * centre (its pose times the model's box) lies closer than `max_centre_distance` times the
  * box's shortest edge to a kept one's is removed. The ratio below 1 leaves room for the
  * poses' errors: copies lying flush along their shortest edge are exactly one edge apart.
  * Only the models whose size at least two measured copies agree on take part (setMinAgreeing(),
  * default 2 here): in a pile the surfaces of touching copies join, a size measured on one copy
  * alone may be far too large, and true copies then seem to interpenetrate (on the IC-BIN
  * juice frames, 1 removed 3, 1 and 1 of the 7, 4 and 6 cartons).
  *
  * A model that this leaves with one instance is removed with it (that instance counts as
  * removed). Models without a size, and frames without a support plane, are left as they
  * are. Deterministic.
  */
class InterpenetrationFilter : public ModelSizeMeasurement
{
public:
  /** \brief A filter whose models need two measured copies agreeing on their size. */
  InterpenetrationFilter() { setMinAgreeing (2); }

  /** \brief Largest distance between the box centres of two instances of one model that
    * interpenetrate, as a share of the box's shortest edge (default 0.8, in [0, 1]).
    */
  ///@{
  void
  setMaxCentreDistance (float ratio)
  {
    max_centre_distance_ = ratio;
  }
  float
  getMaxCentreDistance () const
  {
    return max_centre_distance_;
  }
  ///@}

  /** \brief Remove the interpenetrating instances from `models`.
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
  float max_centre_distance_ = 0.8f; ///< see setMaxCentreDistance()
};

} // namespace mid
