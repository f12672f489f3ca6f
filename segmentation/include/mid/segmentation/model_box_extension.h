#pragma once

#include <mid/registration/object_model.h>
#include <mid/segmentation/model_size.h>

#include <pcl/types.h>

#include <cstddef>
#include <utility>
#include <vector>

namespace mid {

/** \brief What ModelBoxExtender::extend() added to a list of models, so that
  * retractModelExtension() can take it out again.
  */
struct ModelExtension
{
  /** \brief Per model, its number of landmarks before the extension: the added landmarks
    * follow them, and an added observation is one of a landmark from there on.
    */
  std::vector<std::size_t> landmarks_before;
  /** \brief Per model, the observations added, as (instance index, keypoint index). */
  std::vector<std::vector<std::pair<std::size_t, pcl::index_t>>> observations;
};

/** \brief Extends each model by the keypoints its copies show inside their boxes on the
  * support plane, for a search of more copies (not in the paper).
  *
  * A model's landmarks are the keypoints that matched between the copies that made it: a face
  * that only one found copy shows, or whose keypoints did not match across the found copies,
  * is not in the model, and a copy that shows mostly that face is missed although a found copy
  * shows it with keypoints that would match. On the synthetic benchmark's difficult scenes, 25
  * of 54 missed copies of a found product had 6 or more keypoints within 5 mm and a descriptor
  * distance of 500 of a keypoint on a found copy, only 8 of a landmark (doc/benchmark.md,
  * session 32). Extending a model by every keypoint near its instances brings in the keypoints
  * of touching other products; the box the model's copies occupy on the table bounds the
  * object instead. This step:
  *
  * 1. measures each model's size on the support plane (measureModelSizes(): the box most of
  *    its measured instances agree on, with its frame in the model frame), or takes the one
  *    known for it (setKnownSizes());
  * 2. places that box, grown by the margin, at each instance's pose;
  * 3. gives every keypoint that no instance of any model observes, that lies in such a box and
  *    off the table (farther than the plane tolerance from the support plane), to the instance
  *    whose box it lies deepest in: a new landmark at the keypoint (in the model frame, by that
  *    instance's pose) with its descriptor, observed by that instance.
  *
  * A model without a size (fewer measured instances agree on one than setMinAgreeing() asks,
  * default 1, or a known box that is not valid) is not extended. The added landmarks rest on
  * one view and on the instance's pose: meant for a search of more copies (the guided search),
  * after which retractModelExtension() takes them out again (an instance would otherwise hold
  * keypoints of a neighbour that its grown box reaches, and the model points of it), but for
  * those a new copy observes. Deterministic (the plane's hypotheses are drawn with a fixed
  * seed).
  */
class ModelBoxExtender : public ModelSizeMeasurement
{
public:
  /** \brief The keypoints' descriptors (one per keypoint), which the added landmarks keep.
    * Required.
    */
  ///@{
  void
  setInputDescriptors (const SIFTDescriptorCloud::ConstPtr& descriptors)
  {
    descriptors_ = descriptors;
  }
  const SIFTDescriptorCloud::ConstPtr&
  getInputDescriptors () const
  {
    return descriptors_;
  }
  ///@}

  /** \brief How far beyond its box a keypoint still belongs to an instance (metres, default
    * 0.005, >= 0): the box is measured to a few millimetres.
    */
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

  /** \brief The box each model is known to occupy (one per model, in the order of the models
    * given to extend(), e.g. loaded with its file by loadObjectModel()), placed instead of
    * measuring the models' sizes in the frame: a model detected in a new frame, where its
    * copies are too few or too hidden to measure, is extended within the box its discovery
    * frame measured. A box that is not valid leaves its model as it is. Empty (default):
    * measure the sizes in the frame.
    */
  ///@{
  void
  setKnownSizes (const ModelSizes& sizes)
  {
    known_sizes_ = sizes;
  }
  const ModelSizes&
  getKnownSizes () const
  {
    return known_sizes_;
  }
  ///@}

  /** \brief Extend the models by the keypoints their copies show inside their boxes.
    * \param[in,out] models the frame's models; landmarks, descriptors and observations are
    * appended and the diameters updated (the instances' rms_error is not). Without a support
    * plane nothing changes.
    * \param[out] extension what was added, for retractModelExtension(); one entry per model
    * \return false (with a PCL_ERROR, models unchanged, extension empty) on missing or
    * inconsistent input, a parameter out of range, an observation outside the keypoints, or
    * known sizes (setKnownSizes()) that are not one per model or claim a valid box that is no
    * box (isModelBox())
    */
  bool
  extend (ObjectModels& models, ModelExtension& extension) const;

private:
  SIFTDescriptorCloud::ConstPtr descriptors_;
  float margin_ = 0.005f;
  ModelSizes known_sizes_;
};

/** \brief Take out of the models what ModelBoxExtender::extend() added: the added observations
  * of the instances it extended, then the added landmarks (with their descriptors) that no
  * instance observes after that; the landmarks after them are renumbered. Instances appended
  * since (copies found with the extension) keep their observations, and the added landmarks
  * they observe stay: the model grows by the points of its new copies, as the paper's
  * detection extends a model.
  * \param[in] extension what extend() returned for `models`
  * \param[in,out] models the models, extended and possibly given new instances since, in the
  * same order
  * \return false (with a PCL_ERROR, models unchanged) if `extension` does not fit the models
  * (their number, an instance or landmark count it names, an observation of a missing
  * landmark)
  */
bool
retractModelExtension (const ModelExtension& extension, ObjectModels& models);

} // namespace mid
