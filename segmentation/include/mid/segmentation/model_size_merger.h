#pragma once

#include <mid/registration/object_model.h>
#include <mid/segmentation/model_size.h>

namespace mid {

/** \brief Merges models of one object that share no appearance, by the size of the box their
  * copies occupy on the support plane (not in the paper).
  *
  * A lying carton shows one of four long faces up. When the copies that show one set of faces
  * make one model and the copies that show another make a second, no descriptor links the two
  * (their landmarks lie on different faces), and the paper's rules count the second model's
  * instances as false positives. The depth still says that both models are boxes of one size.
  * This step:
  *
  * 1. fits the frame's support plane (fitSupportPlane());
  * 2. measures, for every instance, the box its object occupies on the plane: the surfaces of
  *    all instances grow at once from their keypoints (growInstanceSurfaces()), stop at
  *    creases where two objects meet, and split a surface that still joins touching copies
  *    between them; a box is fitted to each (fitInstanceBox());
  * 3. gives each model the size that most of its measured instances agree on
  *    (largestSizeGroup(): ties go to the box that the most agree with at twice the
  *    tolerances, then to the smaller surface), when at least `min_agreeing` do;
  * 4. merges two models whose sizes agree within the size tolerance, edge by edge, the smaller
  *    model into the larger: the boxes' frames (axes along the edges in ascending length)
  *    give the transform between the model frames, so the merged poses are those of the box,
  *    right up to the box's symmetries (a half turn of a box, a quarter turn of a square one).
  *    Two models that see different parts of the same copies (the two ends of a carton's face,
  *    whose instances split each copy's surface between them, so that each model takes the
  *    size of a part) are placed by the copies instead: the relative pose of one pair of their
  *    instances, lying within the size's longest edge of each other, replaces the boxes'
  *    transform when it makes two or more pairs coincide, and more than that transform does;
  *    each such pair becomes one instance.
  *    A model whose size disagrees is still merged when one of its measured copies has the
  *    other model's size (the box of that copy then gives the transform): with two copies,
  *    one joined with a neighbour or partly hidden, a model takes the size of the smaller
  *    surface, which is often the hidden one's. When neither model's size is found among the
  *    other's copies (both models took such a size, say), a copy of each that has one size
  *    merges them (their two boxes give the transform), unless more than two copies must
  *    agree on a size (`min_agreeing`). A merged model merges on by its size alone, so a
  *    third model of the product may stay apart where only such a pair of copies links it.
  *
  * 5. when none of the above joins two models, merges them when one model's size is that of a
  *    consensus box of the other's copies (consensusBoxes()): the box of what a copy shares
  *    with the model's other copies, without the neighbour of its height it lies flush with
  *    (setConsensusRadius()). Where each of a model's copies lies flush with a different
  *    neighbour, each copy's own box holds it and the neighbour, and only its consensus box
  *    has the product's size.
  *
  * Two products of one size (within the tolerance) are merged too: the step trades those for
  * the second models of one product, which are far more common on a table of several copies
  * of one product. The split of a join between touching copies follows their keypoints, not
  * the seam: such copies are measured right only when their keypoints cover them.
  * Deterministic (the plane's hypotheses are drawn with a fixed seed).
  */
class ModelSizeMerger : public ModelSizeMeasurement
{
public:
  /** \brief Instances of two merged models whose poses coincide within these (radians,
    * metres) are one instance (mergeModel(); defaults 10 deg and 0.01).
    */
  ///@{
  void
  setDuplicateThresholds (float angle, float distance)
  {
    duplicate_angle_ = angle;
    duplicate_distance_ = distance;
  }
  float
  getDuplicateAngle () const
  {
    return duplicate_angle_;
  }
  float
  getDuplicateDistance () const
  {
    return duplicate_distance_;
  }
  ///@}

  /** \brief The radius of the copies' consensus boxes (consensusBoxes(): metres, default
    * 0.02, finite and >= 0; 0 merges without them). Larger tolerates more disagreement between
    * the copies' poses and views of one surface; a neighbour that reaches less than this past
    * the other copies' edges stays in a copy's consensus box. Seed 3 of the benchmark: 5 and
    * 10 mm merged a soy-milk can with a smaller carton, 20 and 30 mm did not.
    */
  ///@{
  void
  setConsensusRadius (float radius)
  {
    consensus_radius_ = radius;
  }
  float
  getConsensusRadius () const
  {
    return consensus_radius_;
  }
  ///@}

  /** \brief Merge the models of one size.
    * \param[in,out] models the frame's models; merged ones are removed, the others keep their
    * order. Without a support plane nothing changes.
    * \return false (with a PCL_ERROR, models unchanged) on missing or inconsistent input, a
    * parameter out of range, or an observation outside the keypoints
    */
  bool
  merge (ObjectModels& models) const;

private:
  float duplicate_angle_ = static_cast<float> (10.0 * M_PI / 180.0);
  float duplicate_distance_ = 0.01f;
  float consensus_radius_ = 0.02f;
};

} // namespace mid
