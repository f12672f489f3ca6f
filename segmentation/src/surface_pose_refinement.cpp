#include <mid/registration/landmark_box.h>
#include <mid/registration/model_refinement.h>
#include <mid/segmentation/surface_pose_refinement.h>

#include <Eigen/Eigenvalues>
#include <Eigen/Geometry>
#include <pcl/console/print.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace mid {

namespace {

using Vector6f = Eigen::Matrix<float, 6, 1>;
using Matrix6f = Eigen::Matrix<float, 6, 6>;

/** Huber scale of a point-to-plane residual (metres): about the sensor's depth noise. */
constexpr float kSurfaceHuber = 0.002f;
/** Huber scale of a landmark residual (metres): the inlier threshold of the paper's RANSAC. */
constexpr float kLandmarkHuber = 0.005f;
/** Smallest eigenvalue, relative to the largest, of a motion the surface constrains. */
constexpr float kMinConstraint = 0.02f;
/** Gauss-Newton steps per pose and round. */
constexpr int kPoseSteps = 3;
/** Partner normals must lie within 45 deg of the carried sample's normal. */
const float kMinNormalCosine = std::cos (static_cast<float> (M_PI) / 4.0f);
/** Normals: a 5 x 5 grid of pixels `kNormalStride` apart, points within kNormalRadius of the
  * centre, at least kNormalMinPoints of them.
  */
constexpr int kNormalStride = 2;
constexpr float kNormalRadius = 0.015f;
constexpr int kNormalMinPoints = 10;

/** Unit surface normals of an organized frame's pixels, towards the camera, computed when first
  * asked for (plane fit over a small grid around the pixel).
  */
class NormalMap
{
public:
  explicit NormalMap (const pcl::PointCloud<pcl::PointXYZ>& cloud)
  : cloud_ (cloud)
  , normals_ (cloud.size(), Eigen::Vector3f::Zero())
  , state_ (cloud.size(), kUnknown)
  {}

  /** The normal at pixel (u, v), inside the frame; false where the depth gives none. */
  bool
  at (int u, int v, Eigen::Vector3f& normal)
  {
    const std::size_t pixel =
        static_cast<std::size_t> (v) * cloud_.width + static_cast<std::size_t> (u);
    if (state_[pixel] == kUnknown)
      state_[pixel] = compute (u, v, normals_[pixel]) ? kValid : kInvalid;
    normal = normals_[pixel];
    return state_[pixel] == kValid;
  }

private:
  enum : std::uint8_t { kUnknown, kValid, kInvalid };

  bool
  compute (int u0, int v0, Eigen::Vector3f& normal) const
  {
    const auto width = static_cast<int> (cloud_.width),
               height = static_cast<int> (cloud_.height);
    const Eigen::Vector3f centre = point (u0, v0);
    if (!centre.allFinite())
      return false;
    Eigen::Vector3f sum = Eigen::Vector3f::Zero();
    Eigen::Matrix3f outer = Eigen::Matrix3f::Zero();
    int count = 0;
    for (int dv = -2; dv <= 2; ++dv)
      for (int du = -2; du <= 2; ++du) {
        const int u = u0 + du * kNormalStride, v = v0 + dv * kNormalStride;
        if (u < 0 || v < 0 || u >= width || v >= height)
          continue;
        const Eigen::Vector3f p = point (u, v);
        if (!p.allFinite() || (p - centre).norm() > kNormalRadius)
          continue;
        const Eigen::Vector3f d = p - centre;
        sum += d;
        outer += d * d.transpose();
        ++count;
      }
    if (count < kNormalMinPoints)
      return false;
    const Eigen::Vector3f mean = sum / static_cast<float> (count);
    const Eigen::Matrix3f covariance =
        outer / static_cast<float> (count) - mean * mean.transpose();
    Eigen::SelfAdjointEigenSolver<Eigen::Matrix3f> solver;
    solver.computeDirect (covariance);
    normal = solver.eigenvectors().col (0);
    if (!normal.allFinite())
      return false;
    if (normal.dot (centre) > 0.0f)
      normal = -normal;
    return true;
  }

  Eigen::Vector3f
  point (int u, int v) const
  {
    return cloud_[static_cast<std::size_t> (v) * cloud_.width +
                  static_cast<std::size_t> (u)]
        .getVector3fMap();
  }

  const pcl::PointCloud<pcl::PointXYZ>& cloud_;
  std::vector<Eigen::Vector3f, Eigen::aligned_allocator<Eigen::Vector3f>> normals_;
  std::vector<std::uint8_t> state_;
};

/** A point of an instance's surface and its normal (camera frame). */
struct SurfaceSample
{
  Eigen::Vector3f point;
  Eigen::Vector3f normal;
  EIGEN_MAKE_ALIGNED_OPERATOR_NEW
};
using SurfaceSamples =
    std::vector<SurfaceSample, Eigen::aligned_allocator<SurfaceSample>>;

/** The frame's pixels an instance's box (placed by `pose`, grown by `margin`) may cover: the
  * image rectangle around its projected corners, clipped to the frame; the whole frame when a
  * corner lies behind the camera.
  */
void
projectedBox (const LandmarkBox& box,
              const Eigen::Matrix4f& pose,
              float margin,
              const FramePinhole& pinhole,
              int width,
              int height,
              Eigen::Vector4i& window)
{
  window << 0, 0, width - 1, height - 1;
  const Eigen::Affine3f to_camera (pose);
  const Eigen::Vector3f half = box.half_extent.array() + margin;
  Eigen::Vector2f low = Eigen::Vector2f::Constant (std::numeric_limits<float>::max());
  Eigen::Vector2f high = -low;
  for (int corner = 0; corner < 8; ++corner) {
    const Eigen::Vector3f sign ((corner & 1) ? 1.0f : -1.0f,
                                (corner & 2) ? 1.0f : -1.0f,
                                (corner & 4) ? 1.0f : -1.0f);
    const Eigen::Vector3f p =
        to_camera * (box.center + box.axes * sign.cwiseProduct (half));
    if (!(p.z() > 1e-6f))
      return;
    const Eigen::Vector2f pixel (
        static_cast<float> (pinhole.fx * p.x() / p.z() + pinhole.cx),
        static_cast<float> (pinhole.fy * p.y() / p.z() + pinhole.cy));
    low = low.cwiseMin (pixel);
    high = high.cwiseMax (pixel);
  }
  window << std::max (0, static_cast<int> (std::floor (low.x()))),
      std::max (0, static_cast<int> (std::floor (low.y()))),
      std::min (width - 1, static_cast<int> (std::ceil (high.x()))),
      std::min (height - 1, static_cast<int> (std::ceil (high.y())));
}

/** The instance's surface samples (see SurfacePoseRefinement, step 1). */
void
collectSamples (const pcl::PointCloud<pcl::PointXYZ>& cloud,
                const FramePinhole& pinhole,
                NormalMap& normals,
                const LandmarkBox& box,
                const Eigen::Matrix4f& pose,
                int step,
                float margin,
                SurfaceSamples& samples)
{
  samples.clear();
  Eigen::Vector4i window;
  projectedBox (box,
                pose,
                margin,
                pinhole,
                static_cast<int> (cloud.width),
                static_cast<int> (cloud.height),
                window);
  const Eigen::Affine3f to_model (pose.inverse());
  for (int v = window[1]; v <= window[3]; v += step)
    for (int u = window[0]; u <= window[2]; u += step) {
      const Eigen::Vector3f p = cloud[static_cast<std::size_t> (v) * cloud.width +
                                      static_cast<std::size_t> (u)]
                                    .getVector3fMap();
      Eigen::Vector3f n;
      if (p.allFinite() && box.distanceTo (to_model * p) <= margin &&
          normals.at (u, v, n))
        samples.push_back ({p, n});
    }
}

/** Gauss-Newton normal equations of a 6-vector increment (rotation, translation). */
struct NormalEquations
{
  Matrix6f hessian = Matrix6f::Zero();
  Vector6f gradient = Vector6f::Zero();

  /** One scalar residual r with Jacobian row J and weight w. */
  void
  add (const Vector6f& jacobian, float residual, float weight)
  {
    hessian.noalias() += weight * jacobian * jacobian.transpose();
    gradient.noalias() += weight * residual * jacobian;
  }
};

/** Huber weight of a residual of size `size` at scale `scale`. */
float
huber (float size, float scale)
{
  return size <= scale ? 1.0f : scale / size;
}

/** What a pose step needs besides the pose being refined. */
struct PoseProblem
{
  const pcl::PointCloud<pcl::PointXYZ>* cloud;
  const FramePinhole* pinhole;
  NormalMap* normals;
  const KeypointCloud* keypoints;
  const ObjectModel* model;
  float max_distance;
  float surface_weight;
  float length; ///< the model's size, to compare rotations with translations (metres)
};

/** Adds the point-to-plane residuals of sample z (model frame, normal n) against every other
  * instance (see SurfacePoseRefinement, step 2).
  */
void
addSurfaceTerms (const PoseProblem& problem,
                 std::size_t own,
                 const Eigen::Vector3f& z,
                 const Eigen::Vector3f& n,
                 NormalEquations& equations)
{
  const auto& cloud = *problem.cloud;
  const auto width = static_cast<int> (cloud.width),
             height = static_cast<int> (cloud.height);
  for (std::size_t i = 0; i < problem.model->instances.size(); ++i) {
    if (i == own)
      continue;
    const Eigen::Matrix4f& pose = problem.model->instances[i].pose;
    const Eigen::Matrix3f rotation = pose.topLeftCorner<3, 3>();
    const Eigen::Vector3f x = rotation * z + pose.topRightCorner<3, 1>();
    int u = 0, v = 0;
    if (!problem.pinhole->project (x, width, height, u, v))
      continue;
    const Eigen::Vector3f q =
        cloud[static_cast<std::size_t> (v) * cloud.width + static_cast<std::size_t> (u)]
            .getVector3fMap();
    Eigen::Vector3f nq;
    if (!q.allFinite() || (x - q).norm() > problem.max_distance ||
        !problem.normals->at (u, v, nq) || (rotation * n).dot (nq) < kMinNormalCosine)
      continue;
    const Eigen::Vector3f normal = rotation.transpose() * nq;
    const float residual = nq.dot (x - q);
    // d(n . (z + w x z + t))/d(w, t) = (z x n, n).
    Vector6f jacobian;
    jacobian << z.y() * normal.z() - z.z() * normal.y(),
        z.z() * normal.x() - z.x() * normal.z(),
        z.x() * normal.y() - z.y() * normal.x(), normal;
    equations.add (jacobian,
                   residual,
                   problem.surface_weight * huber (std::abs (residual), kSurfaceHuber));
  }
}

/** Restricts the surface's normal equations to the motions the surface constrains: those
  * along the eigenvectors of its Hessian (rotations scaled by `length`, so that both parts are
  * in metres) whose eigenvalue reaches kMinConstraint of the largest. Along the others (a
  * plane sliding along itself, a box along its edge) the surface's pull comes only from the
  * errors of its normals; the landmarks alone decide there (Zhang, Kaess and Singh, "On
  * degeneracy of optimization-based state estimation problems", ICRA 2016).
  */
void
keepConstrainedDirections (float length, NormalEquations& surface)
{
  Vector6f scale;
  scale << Eigen::Vector3f::Constant (1.0f / length), Eigen::Vector3f::Ones();
  const Matrix6f scaled = scale.asDiagonal() * surface.hessian * scale.asDiagonal();
  Eigen::SelfAdjointEigenSolver<Matrix6f> solver (scaled);
  const Vector6f& values = solver.eigenvalues();
  Matrix6f projector = Matrix6f::Zero();
  for (int k = 0; k < 6; ++k)
    if (values[k] >= kMinConstraint * values[5])
      projector +=
          solver.eigenvectors().col (k) * solver.eigenvectors().col (k).transpose();
  // Back from the scaled parameters: H = S^-1 P H~ P S^-1, g = S^-1 P g~ with g~ = S g.
  const Vector6f inverse = scale.cwiseInverse();
  surface.hessian =
      inverse.asDiagonal() * (projector * scaled * projector) * inverse.asDiagonal();
  surface.gradient =
      inverse.asDiagonal() * (projector * (scale.asDiagonal() * surface.gradient));
}

/** Gauss-Newton steps on instance `own`'s pose, the other poses and the landmarks fixed (see
  * SurfacePoseRefinement, step 3).
  */
Eigen::Matrix4f
refinePose (const PoseProblem& problem, std::size_t own, const SurfaceSamples& samples)
{
  const ModelInstance& instance = problem.model->instances[own];
  Eigen::Matrix4f to_model = instance.pose.inverse();
  for (int step = 0; step < kPoseSteps; ++step) {
    const Eigen::Matrix3f rotation = to_model.topLeftCorner<3, 3>();
    const Eigen::Vector3f translation = to_model.topRightCorner<3, 1>();
    NormalEquations equations;
    if (problem.surface_weight > 0.0f) {
      for (const auto& sample : samples)
        addSurfaceTerms (problem,
                         own,
                         rotation * sample.point + translation,
                         rotation * sample.normal,
                         equations);
      keepConstrainedDirections (problem.length, equations);
    }
    for (std::size_t o = 0; o < instance.keypoints.size(); ++o) {
      const Eigen::Vector3f z =
          rotation *
              (*problem.keypoints)[static_cast<std::size_t> (instance.keypoints[o])]
                  .getVector3fMap() +
          translation;
      const Eigen::Vector3f error =
          z - problem.model->landmarks[static_cast<std::size_t> (instance.landmarks[o])]
                  .getVector3fMap();
      const float weight = huber (error.norm(), kLandmarkHuber);
      // d(z + w x z + t)/d(w, t) = [-[z]x, I], one row per axis.
      Eigen::Matrix<float, 3, 6> jacobian;
      jacobian << 0.0f, z.z(), -z.y(), 1.0f, 0.0f, 0.0f, //
          -z.z(), 0.0f, z.x(), 0.0f, 1.0f, 0.0f,         //
          z.y(), -z.x(), 0.0f, 0.0f, 0.0f, 1.0f;
      for (int axis = 0; axis < 3; ++axis)
        equations.add (jacobian.row (axis).transpose(), error[axis], weight);
    }
    const float damping = 1e-6f * equations.hessian.trace() / 6.0f + 1e-12f;
    const Vector6f delta = -(equations.hessian + damping * Matrix6f::Identity())
                                .ldlt()
                                .solve (equations.gradient);
    if (!delta.allFinite())
      break;
    Eigen::Matrix4f increment = Eigen::Matrix4f::Identity();
    const float angle = delta.head<3>().norm();
    if (angle > 0.0f)
      increment.topLeftCorner<3, 3>() =
          Eigen::AngleAxisf (angle, delta.head<3>() / angle).toRotationMatrix();
    increment.topRightCorner<3, 1>() = delta.tail<3>();
    to_model = increment * to_model;
    if (angle < 1e-5f && delta.tail<3>().norm() < 1e-6f)
      break;
  }
  const Eigen::Matrix4f pose = to_model.inverse();
  return pose.allFinite() ? pose : instance.pose;
}

} // namespace

void
SurfacePoseRefinement::setKeypointSurface (const KeypointSurface& surface)
{
  surface_ = surface;
  has_pinhole_ = surfacePinhole (surface_, pinhole_);
}

std::string
SurfacePoseRefinement::inputProblem (const ObjectModel& model) const
{
  if (!keypoints_)
    return "no input keypoints";
  if (!surface_.organized || surface_.organized->height < 2)
    return "no organized frame";
  if (!has_pinhole_)
    return "no pinhole projection fits the organized frame";
  if (sample_step_ < 1)
    return "the sample step must be at least 1";
  if (!(box_margin_ >= 0.0f) || !std::isfinite (box_margin_))
    return "the box margin must be finite and >= 0";
  if (!(max_distance_ > 0.0f) || !std::isfinite (max_distance_))
    return "the largest correspondence distance must be finite and > 0";
  if (!(surface_weight_ >= 0.0f) || !std::isfinite (surface_weight_))
    return "the surface weight must be finite and >= 0";
  if (max_iterations_ < 1)
    return "the iterations must be at least 1";
  for (const auto& instance : model.instances)
    if (!instance.pose.allFinite())
      return "an instance's pose is not finite";
  return observationProblem (model, keypoints_->size());
}

bool
SurfacePoseRefinement::refine (ObjectModel& model) const
{
  const std::string problem = inputProblem (model);
  if (!problem.empty()) {
    PCL_ERROR ("[mid::SurfacePoseRefinement::refine] %s.\n", problem.c_str());
    return false;
  }
  if (model.instances.size() < 2)
    return true;
  NormalMap normals (*surface_.organized);
  const PoseProblem pose_problem{surface_.organized.get(),
                                 &pinhole_,
                                 &normals,
                                 keypoints_.get(),
                                 &model,
                                 max_distance_,
                                 surface_weight_,
                                 std::max (0.5f * model.diameter, 0.01f)};
  SurfaceSamples samples;
  for (int iteration = 0; iteration < max_iterations_; ++iteration) {
    const LandmarkBox box = computeLandmarkBox (model);
    if (!box.valid)
      break;
    for (std::size_t n = 1; n < model.instances.size(); ++n) {
      collectSamples (*surface_.organized,
                      pinhole_,
                      normals,
                      box,
                      model.instances[n].pose,
                      sample_step_,
                      box_margin_,
                      samples);
      model.instances[n].pose = refinePose (pose_problem, n, samples);
    }
    updateModelLandmarks (model, *keypoints_);
  }
  for (auto& instance : model.instances)
    updateInstanceError (model, *keypoints_, instance);
  updateModelDiameter (model);
  return true;
}

} // namespace mid
