#pragma once

#include <mid/evaluation/ground_truth.h>

#include <Eigen/Core>
#include <opencv2/core/mat.hpp>

#include <string>

namespace mid {
namespace evaluation {

/** \brief Measure, for every annotated instance of a frame, how much of its visible surface
  * another annotated instance of its type shows too (GroundTruthInstance::shared_surface_cells).
  *
  * This is a property of the ground truth alone, for telling the instances that appearance can
  * find from those it cannot: discovery matches a copy's keypoints to another copy's, so a copy
  * that shows only faces no other copy shows has nothing to be matched by. Each instance's
  * visible pixels (its mask, eroded by one pixel so that no background at its border counts;
  * the visible box when it has no mask) with a depth are back-projected and brought into the
  * model frame by the instance's pose; the cubes of a grid of edge `cell_size` they fall in are
  * the surface the instance shows, each with its mean surface normal (from the depth of the
  * pixels two to either side) and the mean direction towards the camera, in the model frame.
  * Two instances of one type share the cubes both show with a transition tilt of at most
  * `max_transition_tilt` between the two views (Morel and Yu, "ASIFT: A new framework for
  * fully affine invariant image comparison", SIAM J. Imaging Sciences 2009: the foreshortening
  * of the affine map from one view of a patch to the other; SIFT hardly matches beyond 2). An
  * instance gets the largest count over the other instances of its type: 0 for a type
  * annotated once. Plain faces count like printed ones, so the count is an upper bound of what
  * appearance can match.
  * \param[in] depth the frame's depth, metres (CV_32FC1; 0 or not finite = no measurement)
  * \param[in] intrinsics the camera matrix K of the frame
  * \param[in] cell_size edge of the grid's cubes, metres (> 0; 0.01 gives about square
  * centimetres of surface)
  * \param[in] max_transition_tilt largest transition tilt between the two views of a shared
  * cube (>= 1; 2 is SIFT's limit)
  * \param[in,out] frame the annotations; each instance's shared_surface_cells is set, or -1 for
  * all on failure
  * \return false (with a PCL_ERROR naming the problem) if depth is empty or not CV_32FC1, a mask
  * differs from the depth's size, K cannot back-project (zero focal length) or cell_size is not
  * positive, or max_transition_tilt is below 1
  */
bool
measureSharedSurface (const cv::Mat& depth,
                      const Eigen::Matrix3f& intrinsics,
                      float cell_size,
                      float max_transition_tilt,
                      GroundTruthFrame& frame);

/** \brief measureSharedSurface() counting only the cubes that show texture in both views.
  *
  * Plain surface (a can's white lid, a carton's blank side) gives SIFT nothing to match, however
  * much of it two copies share. Here a cube counts only if, in each of the two views, the mean
  * local contrast of its pixels reaches `min_contrast`: the standard deviation of the grey
  * levels in the 5 x 5 window around a pixel, over the pixels whose window lies wholly on the
  * instance's visible part (so that neither the background nor an occluder adds to it). On the
  * synthetic benchmark's Kinect-like images, plain faces give 1 to 1.5 grey levels (the
  * sensor's noise), printed ones 6 to 17 in the median. The count is still an upper bound: a
  * textured cube need not hold a keypoint that SIFT finds in both views, and the crease
  * between two faces of different shading counts as texture (a Kinect-like depth is too
  * coarse to tell it from a printed edge).
  * \param[in] depth the frame's depth, metres (CV_32FC1; 0 or not finite = no measurement)
  * \param[in] image the frame's colour (BGR) or grey image, 8 bit, the depth's size; may be
  * empty when min_contrast is 0
  * \param[in] intrinsics the camera matrix K of the frame
  * \param[in] cell_size edge of the grid's cubes, metres (> 0)
  * \param[in] max_transition_tilt largest transition tilt between the two views of a shared
  * cube (>= 1)
  * \param[in] min_contrast the mean local contrast (grey levels) from which a cube is textured
  * in a view; 0 = no texture test (the overload above)
  * \param[in,out] frame the annotations; each instance's shared_surface_cells is set, or -1 for
  * all on failure
  * \return false (with a PCL_ERROR naming the problem) on the overload above's errors, if
  * min_contrast is negative or not finite, or if the texture test is asked for and the image is
  * not an 8-bit grey or BGR image of the depth's size
  */
bool
measureSharedSurface (const cv::Mat& depth,
                      const cv::Mat& image,
                      const Eigen::Matrix3f& intrinsics,
                      float cell_size,
                      float max_transition_tilt,
                      float min_contrast,
                      GroundTruthFrame& frame);

/** \brief measureSharedSurface() for every frame of a BOP scene folder, reading the camera of
  * each image from scene_camera.json (cam_K, depth_scale in millimetres per depth unit), its
  * depth from `depth/<image>.png` (16 bit) and, for the texture test, its colour image from
  * `rgb/<image>.png` (or `.jpg`).
  * \param[in] folder the scene folder the scene was loaded from (loadBopScene())
  * \param[in] cell_size edge of the grid's cubes, metres (> 0)
  * \param[in] max_transition_tilt largest transition tilt between the two views of a shared
  * cube (>= 1)
  * \param[in] min_contrast the mean local contrast (grey levels) from which a cube is textured
  * in a view; 0 = no texture test, and no colour image is read
  * \param[in,out] scene the scene's frames; every instance's shared_surface_cells is set, or -1
  * for all on failure
  * \return false (with a PCL_ERROR naming the file and the problem) if scene_camera.json lacks a
  * frame or is malformed, a depth image is missing or not 16 bit, a colour image the texture
  * test needs is missing, or a frame cannot be measured
  */
bool
measureSharedSurface (const std::string& folder,
                      float cell_size,
                      float max_transition_tilt,
                      float min_contrast,
                      GroundTruthScene& scene);

} // namespace evaluation
} // namespace mid
