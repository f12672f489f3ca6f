#pragma once

#include <mid/registration/object_model.h>

#include <cmath>

namespace mid {

/** \brief True if two instances lie on one physical object: the centroid of their observed
  * keypoints are closer than the larger of their RMS radii (the RMS distance of an instance's
  * keypoints from their centroid).
  *
  * Copies of an object cannot interpenetrate, so two instances of one object (or of two
  * models) whose keypoints intermix describe one physical object. On one face of a box, two
  * sets of keypoints have nearby centroids (a fraction of the face); on two copies side by
  * side the centroids are about an object's width apart, more than the radius of either set
  * (about 0.4 widths for keypoints spread over a face).
  * \param[in] keypoints the frame's keypoints, which the instances index
  * \param[in] a one instance (its keypoints)
  * \param[in] b the other instance
  * \return false if either instance observes no keypoint
  */
bool
instancesOverlap (const KeypointCloud& keypoints,
                  const ModelInstance& a,
                  const ModelInstance& b);

/** \brief True if two instances look like two faces of one physical copy: their keypoint
  * footprints meet (the centroids of their observed keypoints are closer than the sum of their
  * RMS radii) and they face different ways (the mean normals of their keypoints differ by at
  * least min_angle).
  *
  * Looser than instancesOverlap() in distance: the keypoints of two faces of one copy (the top
  * and a side of a box) adjoin without intermixing. With keypoints spread evenly over the
  * faces, their centroids lie 0.45 sums of radii apart on the top and long side of a
  * 20 x 10 x 5 cm box, 0.87 on two faces of a cube. The same faces of two copies side by side
  * lie 1.22 sums apart when square, but only 0.77 when twice as long as wide and touching
  * along their long sides; such copies rest the same way up and show parallel faces, which
  * the angle tells apart.
  * \param[in] keypoints the frame's keypoints, which the instances index (with normals)
  * \param[in] a one instance (its keypoints)
  * \param[in] b the other instance
  * \param[in] min_angle the mean normals must differ by at least this (radians; default
  * 45 deg, half way between the parallel faces of copies side by side and the perpendicular
  * faces of a box)
  * \return false if either instance observes no keypoint or its keypoints' normals point too
  * many ways to have a mean direction (non-finite normals are skipped)
  */
bool
instancesAdjoin (const KeypointCloud& keypoints,
                 const ModelInstance& a,
                 const ModelInstance& b,
                 float min_angle = static_cast<float> (M_PI / 4.0));

/** \brief Remove the instances of a model that lie on the same physical object as an instance
  * observing at least as many keypoints (on a tie the earlier instance stays); an object with
  * a repeated pattern on one face, such as two copies of a logo, gives such pairs. The
  * remaining instances keep their order.
  * \param[in] keypoints the frame's keypoints, which the instances index
  * \param[in,out] model the model whose instances are checked
  * \return the number of instances removed
  */
std::size_t
removeOverlappingInstances (const KeypointCloud& keypoints, ObjectModel& model);

/** \brief Merge models of which an instance lies on the same physical copy as an instance of
  * another model: both then describe the same object, and the pose of each instance gives the
  * transform between the two model frames.
  *
  * Models are visited largest first (most observations). A smaller model B is merged into a
  * larger model A through one pair of instances taken as one copy: the pair that overlaps
  * (instancesOverlap()) with the most observations, or without one the pair that adjoins
  * (instancesAdjoin()) with the most observations. B is brought into A's frame by that pair;
  * landmarks of B observed by a keypoint that also observes a landmark of A become that
  * landmark; B's instance of the pair joins A's (their keypoints are added to it), B's other
  * instances join an instance of A they overlap or whose pose they take in A's frame (another
  * copy that shows both faces), or else become new instances of A.
  * Complements appearance-based merging: the two models may share no descriptor at all when
  * they were built from different keypoints of one face (overlapping instances) or from two
  * faces of the object that only one copy shows together (adjoining instances).
  * \param[in] keypoints the frame's keypoints, which the instances index
  * \param[in,out] models the models; merged ones are removed
  * \param[in] max_angle, max_distance an instance of B whose pose, in A's frame, lies within
  *            these (radians, metres) of an instance of A is that instance (defaults: those of
  *            DiscoveryParameters::duplicate_angle and duplicate_distance)
  * \return the number of models merged into others
  */
std::size_t
mergeOverlappingModels (const KeypointCloud& keypoints,
                        ObjectModels& models,
                        float max_angle = static_cast<float> (10.0 * M_PI / 180.0),
                        float max_distance = 0.01f);

} // namespace mid
