#pragma once

#include <mid/registration/object_model.h>
#include <mid/segmentation/photometric_verification.h>

#include <cstddef>
#include <string>

namespace mid {

/** \brief Splits a model whose instances fall into groups that do not look alike: one model
  * per group (not in the paper).
  *
  * Every stage that joins copies into one model (a cluster, a merge of two models, an instance
  * detected with a few matches) rests on a few keypoints whose descriptors and geometry agree.
  * Two products whose printed faces share a layout and a font can pass all of them: a row of
  * small apple juice cartons and a row of soy milk cartons become one model. Their grey
  * levels tell them apart: moved by the relative pose of two instances, the surface around one
  * instance's keypoints correlates with the other's when both are copies of one print (0.7 to
  * 0.95 on the synthetic benchmark's development frames) and hardly at all across two prints
  * (-0.2 to 0.25).
  *
  * For every pair of the model's instances, the verification's correlation is computed on
  * their relative pose (PhotometricVerification::correlation(), a cluster from one instance's
  * keypoints to the other's). Instances whose correlation reaches the verification's minimum
  * are linked, and the linked groups of two or more instances are the candidate objects. The
  * model is split only when there are at least two such groups and every two of them were
  * compared at least once (some pair of their instances shows surface in common): groups that
  * never see a common surface (two faces of one product, joined through a third copy's view)
  * may well be one object and stay together. An instance linked to no other joins the group it
  * correlates with best, or the largest group when it was compared with none. Each group
  * becomes a model of its instances and the landmarks they observe (extractModelPart()).
  *
  * Deterministic: no random draws.
  */
class AppearanceModelSplitter
{
public:
  /** \brief The verification that compares two instances, with the frame, its grey levels,
    * the keypoints' pixels and the thresholds (its minimum correlation links two instances).
    * Required.
    */
  ///@{
  void
  setVerification (const PhotometricVerification& verification)
  {
    verification_ = verification;
  }
  const PhotometricVerification&
  getVerification () const
  {
    return verification_;
  }
  ///@}

  /** \brief Split `model` into the groups of instances that look alike.
    * \param[in] model a model whose instances index the verification's keypoint pixels
    * \param[out] parts the model's parts, one per group, in the order of each group's first
    * instance; `model` itself when nothing splits it; cleared on failure
    * \return false (with a PCL_ERROR) if an instance observes a keypoint that has no pixel or
    * a landmark the model does not have, or the verification cannot run (no projection, no
    * grey levels, a parameter out of range)
    */
  bool
  split (const ObjectModel& model, ObjectModels& parts) const;

private:
  /** \brief What is wrong with the input for `model`; empty if nothing. */
  std::string
  inputProblem (const ObjectModel& model) const;

  PhotometricVerification verification_;
};

} // namespace mid
