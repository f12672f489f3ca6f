#pragma once

#include <mid/registration/object_model.h>
#include <mid/segmentation/model_size.h>

namespace mid {

/** \brief Drop the observations that lie outside the box a model's copies occupy on the
  * support plane (not in the paper).
  *
  * In a row of copies standing apart, one cluster links every copy to its neighbour, and a
  * model built from it may take the print of a copy and of its neighbour as one object: its
  * instances then hold keypoints of two copies each, one instance may lie where its keypoints
  * are not, and no instance holds the keypoints of one copy alone (the paper's scoring asks
  * 90 %). The landmark box (ObjectModel, pruneUnexplainedObservations()) then spans both
  * copies and bounds nothing; the box of the model's size measured on the table does.
  *
  * A model whose measured copies agree on its size (ModelSize, at least getMinAgreeing() of
  * them, default 2: one copy measured may be one joined with a neighbour) has that box in its
  * frame: the box of the copy the size came from, placed by that copy's instance
  * (ModelSize::box_in_model). An observation whose keypoint, brought into the
  * model frame by its instance's pose, lies farther than the margin outside that box is
  * dropped; an instance left with no observation is removed (its pose puts the box where none
  * of its keypoints lie; one that had none to begin with stays), unless the model would keep
  * fewer than two instances with observations (the model is then left as it is); a landmark
  * no instance observes any longer is removed with its descriptors. Models without such a size, and all
  * models when no support plane is found, are left as they are. Poses do not change.
  */
class ModelBoxPruning : public ModelSizeMeasurement
{
public:
  ModelBoxPruning() { setMinAgreeing (2); }

  /** \brief How far (metres, default 0.02, >= 0) a kept observation may lie outside the box. */
  ///@{
  void
  setMargin (float margin)
  {
    margin_ = margin;
  }
  float
  getMargin () const
  {
    return margin_;
  }
  ///@}

  /** \brief Drop the observations outside their model's box, as the class says.
    * \param[in,out] models the models (their observations index the input keypoints); each
    * pruned model's diameter is updated, its frame not centred again
    * \param[out] dropped how many observations were dropped (0 on failure)
    * \return false, with a PCL_ERROR and the models unchanged, if an input is missing or
    * inconsistent (SupportPlaneMeasurement; a model's descriptors that do not match its
    * landmarks) or a parameter is out of its range
    */
  bool
  prune (ObjectModels& models, std::size_t& dropped) const;

private:
  float margin_ = 0.02f; ///< see setMargin()
};

} // namespace mid
