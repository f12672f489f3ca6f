#pragma once

#include <mid/features/keypoint_types.h>

#include <Eigen/Core>
#include <Eigen/StdVector>
#include <pcl/types.h>

#include <string>
#include <vector>

namespace mid {

/** \brief One instance of a discovered object in a frame. */
struct ModelInstance
{
  /** \brief Rigid pose mapping model coordinates to camera coordinates (metres). */
  Eigen::Matrix4f pose = Eigen::Matrix4f::Identity();
  /** \brief The frame's keypoints observed on this instance (indices into the keypoint cloud),
    * and for each the model landmark it observes (index into ObjectModel::landmarks; both
    * vectors have the same size).
    */
  ///@{
  pcl::Indices keypoints;
  std::vector<int> landmarks;
  ///@}
  /** \brief Root mean square of |pose * landmark - keypoint| over the observations (metres). */
  float rms_error = 0.0f;

  EIGEN_MAKE_ALIGNED_OPERATOR_NEW
};

/** \brief Instances of one object (Eigen-aligned, as ModelInstance holds a fixed-size matrix). */
using ModelInstances =
    std::vector<ModelInstance, Eigen::aligned_allocator<ModelInstance>>;

/** \brief A sparse 3D model of an object discovered from its repeated instances, and where those
  * instances are.
  *
  * The model frame is centred on the landmarks' centroid, with the axes of the camera at the
  * reference instance (a model made by SizeInstanceSearch from objects of one size: the axes
  * of its first copy's box). Each landmark is a 3D point on the object with the normal there; every
  * observation of a landmark keeps its SIFT descriptor, so the model can be matched against new
  * keypoints (descriptor_landmarks says which landmark each descriptor belongs to).
  */
struct ObjectModel
{
  /** \brief Landmarks in the model frame: position and unit normal. */
  KeypointCloud landmarks;
  /** \brief Descriptors of the landmarks' observations. */
  SIFTDescriptorCloud descriptors;
  /** \brief For each descriptor, the landmark it describes (index into landmarks; same size as
    * descriptors).
    */
  std::vector<int> descriptor_landmarks;
  /** \brief Largest distance between two landmarks (metres). */
  float diameter = 0.0f;
  /** \brief Where the object is in the frame it was discovered in (or detected in). */
  ModelInstances instances;
};

/** \brief Every object discovered in a frame. */
using ObjectModels = std::vector<ObjectModel>;

/** \brief The size of the box a model's copies occupy on the support plane (not in the paper):
  * measured in a frame (ModelSizeMeasurement), kept with the model in its files
  * (saveObjectModel()), and reported in the results.
  */
struct ModelSize
{
  /** \brief True if at least the required number of measured instances agree on `size`. */
  bool valid = false;
  /** \brief How many measured instances agree on `size` (0 if none is measured). */
  int agreeing = 0;
  /** \brief Box edges (metres), ascending. */
  Eigen::Vector3f size = Eigen::Vector3f::Zero();
  /** \brief Box frame -> model frame: the box of the instance that gave `size`, in the model
    * frame (axes along the edges in the order of `size`, origin at its centre).
    */
  Eigen::Matrix4f box_in_model = Eigen::Matrix4f::Identity();

  EIGEN_MAKE_ALIGNED_OPERATOR_NEW
};

/** \brief One ModelSize per model. */
using ModelSizes = std::vector<ModelSize, Eigen::aligned_allocator<ModelSize>>;

/** \brief What a box that claims to be valid must be, in words (isModelBox()). */
inline constexpr const char* MODEL_BOX_RULE =
    "a box is 3 positive ascending edges, a number of copies of at least 1 and a 4x4 "
    "rigid "
    "pose";

/** \brief Whether a box that claims to be valid is one: its edges positive, finite and
  * ascending, one copy or more agreeing, its pose rigid (a rotation within 1e-3, not a mirror,
  * the last row 0 0 0 1). The model files' writer and reader and
  * ModelBoxExtender::setKnownSizes() ask the same; `valid` itself is not looked at.
  */
bool
isModelBox (const ModelSize& box);

/** \brief What is wrong with a model's observations, for the steps that check their input:
  * an instance with unequal numbers of keypoints and landmarks, or an observation of a
  * keypoint outside [0, keypoints) or of a landmark the model does not have.
  * \param[in] model the model
  * \param[in] keypoints how many keypoints the frame has
  * \return the problem in words; empty if there is none
  */
std::string
observationProblem (const ObjectModel& model, std::size_t keypoints);

/** \brief What is wrong with a model's descriptors: their number differs from that of
  * descriptor_landmarks, or one describes a landmark the model does not have.
  * \return the problem in words; empty if there is none
  */
std::string
descriptorProblem (const ObjectModel& model);

/** \brief For each instance of a model, the group of copies whose relative poses rest on
  * their print (not in the paper): instances that observe a common landmark, directly or
  * through other instances, are in one group. Within a group the relative poses come from
  * keypoints matched on the same surface (or on two that look alike: a product with one print
  * layout on several sides can be matched across them); between groups from something that
  * cannot tell the faces of a box apart (the box a copy occupies on the table,
  * SizeInstanceSearch and ModelSizeMerger), and are right up to the box's symmetries: a picker
  * that needs the print side (a label, an opening) can trust it within one group only.
  * Observations of landmarks the model does not have are ignored (no crash); steps that need
  * valid observations check them with observationProblem() first.
  * \param[in] model the model
  * \return one group number per instance, numbered 0, 1, ... in the order of each group's
  * first instance (all 0 when every copy is linked by its print)
  */
std::vector<int>
sharedLandmarkGroups (const ObjectModel& model);

/** \brief Recompute an instance's rms_error from its observations (0 when it has none).
  * \param[in] model the model whose landmarks the instance observes
  * \param[in] keypoints the frame's keypoints the instance's indices refer to
  * \param[in,out] instance its pose and observations are read, its rms_error written; its
  * indices must be valid for model and keypoints (not checked)
  */
void
updateInstanceError (const ObjectModel& model,
                     const KeypointCloud& keypoints,
                     ModelInstance& instance);

/** \brief Add the observations of `extra` (another view of the same physical copy, whose
  * landmark indices already refer to the same model) to `target`, skipping keypoints `target`
  * already observes; its pose stays.
  * \param[in,out] target the instance that gains observations
  * \param[in] extra the instance whose observations are added
  */
void
joinObservations (ModelInstance& target, const ModelInstance& extra);

/** \brief True if two model -> camera poses place the model within max_angle (radians) and
  * max_distance (metres, measured at the model point `center`) of each other.
  * \param[in] a first pose, model -> camera
  * \param[in] b second pose, model -> camera
  * \param[in] center model point at which the distance is measured (model frame, metres)
  * \param[in] max_angle the relative rotation must be smaller than this (radians)
  * \param[in] max_distance the two images of center must be closer than this (metres)
  * \return true if both bounds hold (false for NaN input)
  */
bool
posesCoincide (const Eigen::Matrix4f& a,
               const Eigen::Matrix4f& b,
               const Eigen::Vector3f& center,
               float max_angle,
               float max_distance);

/** \brief Remove the landmarks flagged in `remove` (one flag per landmark) with their
  * descriptors, renumbering the rest in the descriptors' and instances' references. No
  * instance may observe a removed landmark (not checked).
  */
void
removeLandmarks (const std::vector<bool>& remove, ObjectModel& model);

/** \brief The part of a model that some of its instances see: those instances, the landmarks
  * they observe (renumbered in their order) and those landmarks' descriptors, in the same
  * model frame.
  * \param[in] model the whole model
  * \param[in] instances indices into model.instances of the instances to keep, in the order
  * the part lists them; each must be valid and observe valid landmarks (not checked)
  * \param[out] part the part, its diameter recomputed (updateModelDiameter())
  */
void
extractModelPart (const ObjectModel& model,
                  const std::vector<std::size_t>& instances,
                  ObjectModel& part);

/** \brief Recompute a model's diameter from its landmarks (0 for fewer than two).
  * \param[in,out] model its landmarks are read, its diameter written
  */
void
updateModelDiameter (ObjectModel& model);

/** \brief The centroid of a model's landmarks (model frame, metres); the origin for a model
  * without landmarks.
  */
Eigen::Vector3f
landmarkCentroid (const ObjectModel& model);

/** \brief Move a model's frame to its landmarks' centroid, keeping its axes: the landmarks
  * are shifted and every instance's pose compensates, so each instance still places every
  * landmark where it was in the camera frame (nothing changes for a model without landmarks).
  * The builder's models are centred so; a model whose landmarks were added or taken (merges,
  * a model made from keypoints in the camera frame) is centred again with this.
  * \param[in,out] model its landmarks and its instances' poses are moved
  */
void
centerModelFrame (ObjectModel& model);

/** \brief Add an instance at `pose` that observes some keypoints, each of which becomes a new
  * landmark of the model: its position and normal carried into the model frame, its descriptor
  * taken along. For copies that show the model nothing it already holds (found by their size,
  * say), whose keypoints extend it. The instance's error and the model's diameter are updated;
  * the frame is not centred again (centerModelFrame()).
  * \param[in] keypoints the frame's keypoints (camera frame, metres)
  * \param[in] descriptors one per keypoint
  * \param[in] observed the keypoints the new instance observes (valid indices, not checked)
  * \param[in] pose the new instance's pose, model frame -> camera frame
  * \param[in,out] model the model that gets the landmarks and the instance
  */
void
addInstanceOfKeypoints (const KeypointCloud& keypoints,
                        const SIFTDescriptorCloud& descriptors,
                        const pcl::Indices& observed,
                        const Eigen::Matrix4f& pose,
                        ObjectModel& model);

/** \brief A model of some keypoints: one instance that observes them, each a landmark, the frame
  * at their centroid with the camera's axes (centred like the builder's models, so that the
  * checks that compare two poses at the model origin measure at the object). A seed whose
  * copies are looked for next (the pipeline's models from patches).
  * \param[in] keypoints the frame's keypoints (camera frame, metres)
  * \param[in] descriptors one per keypoint
  * \param[in] observed the keypoints of the model (valid indices, not checked)
  * \return the model; without landmarks and instances when `observed` is empty
  */
ObjectModel
modelOfKeypoints (const KeypointCloud& keypoints,
                  const SIFTDescriptorCloud& descriptors,
                  const pcl::Indices& observed);

/** \brief Remove the flagged instances of each model, keeping the others in order; a model
  * that this leaves with one instance (of several) loses it too, as one copy is no repeated
  * object, and models left without instances are erased.
  * \param[in] remove one list per model, one flag per instance
  * \param[in,out] models the models
  * \return the number of instances removed (with the last ones of the models erased)
  */
std::size_t
removeInstances (const std::vector<std::vector<bool>>& remove, ObjectModels& models);

} // namespace mid
