#pragma once

#include <mid/evaluation/detection_result.h>
#include <mid/evaluation/ground_truth.h>
#include <mid/evaluation/object_symmetry.h>

#include <vector>

namespace mid {
namespace evaluation {

/** \brief The box one valid object's result gives, and the type the object took. */
struct ObjectBox
{
  int type = -1;                                  ///< the BOP obj_id the object took
  Eigen::Vector3f size = Eigen::Vector3f::Zero(); ///< DetectedObject::box_size
  int copies = 0;                                 ///< DetectedObject::box_copies
};

/** \brief How one frame's result scores against its annotations, by the rules of Abbeloos et
  * al. (3DV 2017, Sec. 4.2); see scoreFrame().
  */
struct FrameScore
{
  /** \brief Counted on instances: true positives, false positives, false negatives. */
  ///@{
  int instance_tp = 0;
  int instance_fp = 0;
  int instance_fn = 0;
  ///@}
  /** \brief Counted on pairs (one per repeated object type): true positives, false positives,
    * false negatives.
    */
  ///@{
  int pair_tp = 0;
  int pair_fp = 0;
  int pair_fn = 0;
  ///@}
  /** \brief True if every repeated object type has exactly two instances (the paper's subset
    * for pair scores).
    */
  bool pairs_only = false;
  /** \brief The shared surface (GroundTruthInstance::shared_surface_cells) of each annotated
    * instance of a repeated type that a true positive found, and of each one that none found;
    * instances whose shared surface was not measured are left out.
    */
  ///@{
  std::vector<int> found_shared_cells, missed_shared_cells;
  ///@}
  /** \brief The annotated instances of repeated types that no true positive found (indices into
    * GroundTruthFrame::instances), and, of those, the ones on which an instance of a false
    * positive object lies (a second model of an already found type, or a model of a type
    * annotated once): found, but not counted.
    */
  ///@{
  std::vector<std::size_t> missed_instances, missed_but_located;
  ///@}
  /** \brief Relative pose errors between correctly detected instances of one object: rotation
    * (degrees) and translation (millimetres, at the first instance's object origin).
    */
  ///@{
  std::vector<double> rotation_errors_deg;
  std::vector<double> translation_errors_mm;
  ///@}
  /** \brief The same pairs' rotation errors (degrees) modulo the symmetries of the object's
    * shape (symmetricRotationError()): a pair turned by a symmetry of the shape against the
    * truth (a square carton by a quarter turn about its long axis) is right for a gripper
    * though wrong for the print; equal to rotation_errors_deg for a type without symmetries.
    */
  std::vector<double> symmetric_rotation_errors_deg;
  /** \brief For the same pairs: 1 if the result puts both instances in one group
    * (DetectedInstance::group: their relative pose rests on their print), 0 if in two, -1 if
    * it gives no group to one of them.
    */
  std::vector<int> pair_groups;
  /** \brief Each valid object (one that took a repeated type), in the order of the result:
    * the type it took and its result's box (DetectedObject::box_size and box_copies), for
    * comparing the box with the type's true size.
    */
  std::vector<ObjectBox> object_boxes;
};

/** \brief Score one frame.
  *
  * An instance is correct if at least `min_inside` (the paper: 90 %) of its keypoints lie on
  * one annotated instance (its visible mask, or its visible box without a mask). Each object
  * takes the type most of its correct instances lie on. An object with no correct instance, an
  * object of a type annotated only once, and a second object of an already found type are
  * false positives with all their instances. Within a valid object, a correct instance on a new
  * annotated instance of its type is a true positive, anything else (wrong place, a second
  * detection of one instance) a false positive. Instances of repeated types (two or more
  * annotated) that no true positive found are false negatives; objects that appear once are not
  * expected to be found. On pairs: a valid object with two or more true positives is a true
  * positive pair, any other object a false positive, and a repeated type without one a false
  * negative.
  * \param[in] truth the frame's annotations (loadBopScene())
  * \param[in] result the frame's result (readDetectionResult())
  * \param[in] min_inside fraction of an instance's keypoints that must lie on one annotated
  * instance for it to be correct, in [0, 1]; default 0.9 (the paper)
  * \param[in] symmetries the shape symmetries of the object types (loadBopModelSymmetries()),
  * for FrameScore::symmetric_rotation_errors_deg; default none
  * \return the counts and the relative pose errors
  */
FrameScore
scoreFrame (const GroundTruthFrame& truth,
            const DetectionResult& result,
            double min_inside = 0.9,
            const ObjectSymmetryTable& symmetries = {});

} // namespace evaluation
} // namespace mid
