#pragma once

#include <mid/registration/object_model.h>
#include <mid/segmentation/model_size.h>

#include <cstddef>

namespace mid {

/** \brief Splits a model whose copies occupy boxes of two clearly different sizes on the
  * support plane: two products joined into one model (not in the paper).
  *
  * Every stage that joins copies into one model rests on a few keypoints whose descriptors and
  * geometry agree. Two products whose printed faces share a layout and a font (one brand's
  * apple juice and soy milk cartons) can pass them all, through a merge of their models or a
  * copy detected with a few matches. The depth still tells them apart when their boxes differ:
  * the synthetic benchmark's small apple juice carton (55 x 55 x 157 mm) and soy milk carton
  * (66 x 66 x 189 mm) measure 54-58 x 57-58 x 155-159 and 65-69 x 67-70 x 187-190. This step,
  * the converse of ModelSizeMerger:
  *
  * 1. measures the box every instance of every model occupies on the support plane
  *    (measureInstanceBoxes(): the surfaces of all instances grow at once from their
  *    keypoints and stop at creases and between touching copies);
  * 2. in each model, takes the largest group of instances whose boxes agree on one size
  *    (largestSizeGroup()), then the largest group of one size among the rest;
  * 3. splits the model when both groups have at least the given number of instances
  *    (setMinAgreeing(), at least 2) and their sizes differ on every edge
  *    (SizeAgreement::differOnEveryEdge()). A box measured joined with a touching copy, or
  *    partly hidden, changes one or two edges; its height on the table seldom changes too, so
  *    such a copy does not split its model;
  * 4. gives every other instance (not measured, or of a third size) to the group whose
  *    instances observe more of the landmarks it observes (ties: the larger group);
  * 5. makes each group a model of its instances and the landmarks they observe
  *    (extractModelPart(), same model frame), and looks at both parts again.
  *
  * A model of two products that share one box size stays whole, as do models with fewer than
  * two measured copies of each product. Deterministic (the plane's hypotheses are drawn with
  * a fixed seed).
  */
class ModelSizeSplitter : public ModelSizeMeasurement
{
public:
  /** \brief Each size needs two instances that agree on it by default (setMinAgreeing(),
    * here >= 2: a single copy measured apart from the others is more often a copy joined with
    * a neighbour or partly hidden than another product).
    */
  ModelSizeSplitter() { min_agreeing_ = 2; }

  /** \brief Split the models whose copies occupy boxes of two sizes.
    * \param[in,out] models the frame's models; a split model is replaced by the part of its
    * size group with more instances, and the other part is appended. Without a support plane nothing
    * changes.
    * \param[out] added the number of models added (0 on failure)
    * \return false (with a PCL_ERROR, models unchanged) on missing or inconsistent input, a
    * parameter out of range (setMinAgreeing() below 2 included), or an observation outside
    * the keypoints
    */
  bool
  split (ObjectModels& models, std::size_t& added) const;
};

} // namespace mid
