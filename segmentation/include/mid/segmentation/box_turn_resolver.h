#pragma once

#include <mid/registration/object_model.h>
#include <mid/segmentation/model_size.h>
#include <mid/segmentation/photometric_verification.h>

#include <cstddef>
#include <string>

namespace mid {

/** \brief Turns the copies of a model whose pose rests on the box alone to the turn of the
  * box that looks like the model's other copies (not in the paper).
  *
  * The steps that join copies by their size (SizeInstanceSearch, ModelSizeMerger) pose a copy
  * by its box: right up to the box's symmetries (a half turn about each axis, a quarter turn
  * about an axis whose other two edges are equal), because which face the copy shows is not
  * known to the size. A gripper holding the box by its shape does not care; anything that
  * needs the print does (reading a label, placing the object facing out), and on the
  * benchmark's pair subset 51 of 120 pairs of correctly found copies were turned by 90 or 180
  * degrees (doc/benchmark.md, session 46). Where two such copies show a face in common, the
  * print tells the turn. For each model:
  *
  * 1. its instances fall into groups that observe common landmarks (sharedLandmarkGroups(): a
  *    landmark observed by two instances links them); with one group, every relative pose
  *    rests on the print and nothing is done;
  * 2. the group with the most observations is the reference; the model's box (the size its
  *    measured copies agree on, measureModelSizes(), in the model frame) gives the turns: the
  *    proper rotations about the box's centre that map it onto itself (edges equal within the
  *    size tolerances);
  * 3. each other group is tried in every turn: the instance of the reference with the most
  *    observations and the group's instance with the most are compared by the verification
  *    (PhotometricVerification::compare(), the surface around each one's keypoints moved onto
  *    the other by their relative pose in that turn, both ways);
  * 4. the group takes the turn whose look is confirmed (tested and not rejected) with the
  *    highest correlation, when that turn is not its present one and beats the present one's
  *    correlation by at least `min_gain` (or the present one is untested or rejected): its
  *    instances' poses and the landmarks they observe turn with the box, so every
  *    observation stays where it was.
  *
  * A model without a size (no support plane, or no measured copy) is left as it is, and so is
  * a group whose copies show no face in common with the reference (no turn is tested).
  * Deterministic (the plane's hypotheses are drawn with a fixed seed; no other draw).
  */
class BoxTurnResolver : public ModelSizeMeasurement
{
public:
  /** \brief The verification that compares two copies, with the frame's grey levels (and
    * colours), projection and keypoint pixels, and its thresholds: a turn is confirmed when
    * PhotometricVerification::rejects() does not rule it out. Required; its keypoint surface
    * must be the frame of setKeypointSurface().
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

  /** \brief How much higher the correlation of another turn must be than that of the present
    * one for a group to turn, when the present one is confirmed too (default 0.1, in [0, 2]).
    */
  ///@{
  void
  setMinGain (float gain)
  {
    min_gain_ = gain;
  }
  float
  getMinGain () const
  {
    return min_gain_;
  }
  ///@}

  /** \brief Turn the groups of copies whose print says their box is turned.
    * \param[in,out] models the models (their instances' keypoints index the input keypoints);
    * turned instances get their new pose and rms_error, the landmarks they observe move
    * \param[out] turned the number of instances turned
    * \return false (with a PCL_ERROR naming the problem, the models untouched, turned 0) if an
    * input or a parameter is unusable
    */
  bool
  resolve (ObjectModels& models, std::size_t& turned) const;

private:
  /** \brief What is wrong with the input or the parameters; empty if nothing. */
  std::string
  inputProblem (const ObjectModels& models) const;

  PhotometricVerification verification_;
  float min_gain_ = 0.1f; ///< see setMinGain()
};

} // namespace mid
