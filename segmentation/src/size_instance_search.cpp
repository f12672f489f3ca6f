#include "copy_cutter.h"
#include "free_objects.h"
#include "size_groups.h"

#include <mid/segmentation/instance_extent.h>
#include <mid/segmentation/model_size.h>
#include <mid/segmentation/size_instance_search.h>

#include <pcl/console/print.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace mid {

namespace {

using detail::CopyCutter;
using detail::FreeObject;
using detail::FreeObjects;

/** The model of `size`, -1 if none: the closest (edge by edge) of the models whose size agrees
  * with it, else the first whose size rests on one measured copy alone and which has another
  * copy of `size` (boxOfSize()): with the object, two copies agree on it. `box_in_model` is
  * then the box of `size` in that model.
  */
int
modelOfSize (const Eigen::Vector3f& size,
             const ObjectModels& models,
             const ModelSizes& sizes,
             const std::vector<InstanceExtents>& extents,
             const SizeAgreement& agree,
             Eigen::Matrix4f& box_in_model)
{
  int best = -1;
  float best_difference = std::numeric_limits<float>::infinity();
  for (std::size_t m = 0; m < sizes.size(); ++m) {
    if (!sizes[m].valid || !agree (sizes[m].size, size))
      continue;
    const float difference = (sizes[m].size - size).cwiseAbs().maxCoeff();
    if (difference < best_difference) {
      best = static_cast<int> (m);
      best_difference = difference;
      box_in_model = sizes[m].box_in_model;
    }
  }
  // No two of such a model's measured copies agree (its size is one copy's): ModelSize() has
  // no size of its own, so only its copies' boxes are looked at.
  for (std::size_t m = 0; best < 0 && m < sizes.size(); ++m)
    if (sizes[m].valid && sizes[m].agreeing < 2 &&
        boxOfSize (size, ModelSize(), models[m], extents[m], agree, box_in_model))
      best = static_cast<int> (m);
  return best;
}

/** How close (shortest edges of the object's box) the centres of two boxes of one size lie
  * when they are one copy: a box with shortest edge e holds a sphere of diameter e around its
  * centre (the ratio is InterpenetrationFilter's default, which scales the model's edge).
  */
constexpr float kSameCopyDistance = 0.8f;

/** Where the copies that SizeInstanceSearch finds go: into the model of their size, as
  * instances of their keypoints at their boxes' poses, or into a new model of copies. A
  * keypoint goes to one copy at most.
  */
class CopyPlacement
{
public:
  CopyPlacement (ObjectModels& models,
                 const ModelSizes& sizes,
                 const std::vector<InstanceExtents>& extents,
                 const SizeAgreement& agree,
                 const KeypointCloud& keypoints,
                 const SIFTDescriptorCloud& descriptors)
  : models_ (models)
  , sizes_ (sizes)
  , extents_ (extents)
  , agree_ (agree)
  , keypoints_ (keypoints)
  , descriptors_ (descriptors)
  , taken_ (keypoints.size(), false)
  {}

  /** True if none of the object's keypoints went to a copy yet. */
  bool
  untaken (const FreeObject& object) const
  {
    return std::none_of (
        object.keypoints.begin(), object.keypoints.end(), [this] (pcl::index_t k) {
          return taken_[static_cast<std::size_t> (k)];
        });
  }

  /** The model of the object's size (modelOfSize()), -1 if none; the object joins it unless
    * one of its keypoints went to another copy already, or the model has a copy where it
    * lies (occupied()).
    */
  int
  joinModelOfItsSize (const FreeObject& object)
  {
    Eigen::Matrix4f box_in_model = Eigen::Matrix4f::Identity();
    const int m = modelOfSize (
        object.extent.size, models_, sizes_, extents_, agree_, box_in_model);
    if (m < 0 || !untaken (object) ||
        occupied (models_[static_cast<std::size_t> (m)], box_in_model, object.extent))
      return m;
    addInstanceOfKeypoints (keypoints_,
                            descriptors_,
                            object.keypoints,
                            object.extent.pose * box_in_model.inverse(),
                            models_[static_cast<std::size_t> (m)]);
    take (object);
    return m;
  }

  /** A new model of `copies`. Its frame is the first copy's box frame (centred on the
    * landmarks after).
    */
  void
  addModelOfCopies (const FreeObjects& copies)
  {
    ObjectModel model;
    for (const FreeObject& copy : copies) {
      addInstanceOfKeypoints (
          keypoints_, descriptors_, copy.keypoints, copy.extent.pose, model);
      take (copy);
    }
    centerModelFrame (model);
    models_.push_back (model);
  }

  /** Copies cut by their outline join the model of their size, as objects of it do, if they
    * all have one; else they make a model.
    */
  void
  addCopies (const FreeObjects& copies)
  {
    Eigen::Matrix4f box_in_model;
    if (std::all_of (copies.begin(), copies.end(), [&] (const FreeObject& copy) {
          return modelOfSize (copy.extent.size,
                              models_,
                              sizes_,
                              extents_,
                              agree_,
                              box_in_model) >= 0;
        })) {
      for (const FreeObject& copy : copies)
        joinModelOfItsSize (copy);
      return;
    }
    addModelOfCopies (copies);
  }

  /** The copies placed so far. */
  std::size_t
  found () const
  {
    return found_;
  }

private:
  /** True if an instance of `model` already occupies the box `box` (a copy of the model's
    * box `box_in_model`): its box's centre lies closer than kSameCopyDistance shortest edges
    * to `box`'s (the InterpenetrationFilter's rule). The object is then that copy seen again:
    * its surface, or the part of it that the instance's keypoints leave free.
    */
  static bool
  occupied (const ObjectModel& model,
            const Eigen::Matrix4f& box_in_model,
            const InstanceExtent& box)
  {
    const float reach = kSameCopyDistance * box.size.minCoeff();
    return std::any_of (
        model.instances.begin(),
        model.instances.end(),
        [&] (const ModelInstance& instance) {
          return ((instance.pose * box_in_model).topRightCorner<3, 1>() -
                  box.pose.topRightCorner<3, 1>())
                     .norm() < reach;
        });
  }

  void
  take (const FreeObject& copy)
  {
    for (const auto k : copy.keypoints)
      taken_[static_cast<std::size_t> (k)] = true;
    ++found_;
  }

  ObjectModels& models_;
  const ModelSizes& sizes_;
  const std::vector<InstanceExtents>& extents_;
  SizeAgreement agree_;
  const KeypointCloud& keypoints_;
  const SIFTDescriptorCloud& descriptors_;
  std::vector<bool> taken_;
  std::size_t found_ = 0;
};

/** An object of no model's size may be copies of one touching each other flush, or hold one
  * joined with something else: the object, or else its parts, join the model of their size.
  * The model of the object's (or its parts') size, whether they joined it or not (their
  * keypoints taken, or the model having a copy there already); -1 if none.
  */
int
joinModelOrCutIntoCopies (const FreeObject& object,
                          const ModelSizes& sizes,
                          const CopyCutter& cutter,
                          int min_keypoints,
                          CopyPlacement& placement)
{
  int m = placement.joinModelOfItsSize (object);
  for (std::size_t other = 0; m < 0 && other < sizes.size(); ++other) {
    if (!sizes[other].valid || !placement.untaken (object))
      continue;
    for (const FreeObject& part : cutter.flushCopies (object, sizes[other].size))
      if (part.keypoints.size() >= static_cast<std::size_t> (min_keypoints))
        m = std::max (m, placement.joinModelOfItsSize (part));
    if (m < 0)
      for (const FreeObject& copy : cutter.copyByItsFlatTop (object, sizes[other].size))
        m = placement.joinModelOfItsSize (copy);
  }
  return m;
}

/** Models of the objects of one size (groupsOfOneSize() of the `founders`), each with the
  * copies of that size cut from the other `candidates` (flush copies, one joined with
  * something else by its flat top, or one hidden in part by something in front); then models
  * of the copies that a candidate left holds, joined with each other (by their flat tops) or
  * flush (by its outline). No two copies of a model may be the two ends of one box hidden in
  * the middle (CopyCutter::endsOfOneBox()): the second is left out. `used` marks the objects
  * whose copies were placed, and those of a model left out as such an end.
  */
void
discoverModelsOfCopies (const FreeObjects& objects,
                        const std::vector<std::size_t>& founders,
                        const std::vector<std::size_t>& candidates,
                        const CopyCutter& cutter,
                        const SizeAgreement& agree,
                        const KeypointSurface& surface,
                        int min_keypoints,
                        CopyPlacement& placement,
                        std::vector<bool>& used)
{
  for (const auto& group :
       detail::groupsOfOneSize (objects, founders, agree, surface)) {
    FreeObjects copies;
    std::vector<std::size_t> sources;
    for (const std::size_t o : group)
      if (!used[o]) {
        copies.push_back (objects[o]);
        sources.push_back (o);
      }
    if (copies.empty())
      continue;
    // A size seen once cuts no group of copies (a box may be two of another), but it finds a
    // copy whose own top shows in a join with something else. A size seen twice or more also
    // takes a copy of it that something in front hides in part and that looks like the first
    // (seen once, such a pair waits for pairHiddenCopies(), after the cuts below).
    const bool seen_once = copies.size() < 2;
    const Eigen::Vector3f size = copies.front().extent.size;
    for (const std::size_t o : candidates) {
      if (used[o] || std::find (group.begin(), group.end(), o) != group.end() ||
          std::any_of (group.begin(), group.end(), [&] (std::size_t g) {
            return cutter.endsOfOneBox (objects[g], objects[o]);
          }))
        continue;
      FreeObjects parts;
      if (!seen_once)
        for (const FreeObject& part : cutter.flushCopies (objects[o], size))
          if (part.keypoints.size() >= static_cast<std::size_t> (min_keypoints) &&
              agree (part.extent.size, size))
            parts.push_back (part);
      if (parts.size() < 2)
        parts = cutter.copyByItsFlatTop (objects[o], size);
      if (parts.empty() && !seen_once &&
          detail::colourOverlap (surface, copies.front(), objects[o]) >=
              detail::kMinLoosePairColourOverlap)
        parts = cutter.hiddenCopy (objects[o], size);
      if (parts.empty())
        continue;
      sources.push_back (o);
      copies.insert (copies.end(), parts.begin(), parts.end());
    }
    // A box that something in front hides in the middle shows twice: once is a copy (a
    // candidate's part is tested as the candidate measured, above: a completed hidden copy's
    // box reaches into the middle).
    for (std::size_t c = 1; c < copies.size();) {
      const bool seen_before =
          std::any_of (copies.begin(),
                       copies.begin() + static_cast<std::ptrdiff_t> (c),
                       [&] (const FreeObject& copy) {
                         return cutter.endsOfOneBox (copy, copies[c]);
                       });
      if (seen_before)
        copies.erase (copies.begin() + static_cast<std::ptrdiff_t> (c));
      else
        ++c;
    }
    if (copies.size() < 2)
      continue;
    for (const std::size_t o : sources)
      used[o] = true;
    placement.addModelOfCopies (copies);
  }
  // What is left may be copies of one box touching each other, none measured alone, whose
  // tops or footprint show their edges.
  for (const std::size_t o : candidates) {
    if (used[o])
      continue;
    FreeObjects copies = cutter.copiesOfItsFlatTops (objects[o]);
    if (copies.size() < 2)
      copies = cutter.copiesOfItsOutline (objects[o]);
    if (copies.size() < 2)
      continue;
    used[o] = true;
    placement.addCopies (copies);
  }
}

/** Two of the `founders` (the objects that may found a model: no shorter edge than the
  * models', standing alone when asked) not yet `used`, one a copy of the other's box that
  * something in front hides in part (CopyCutter::hiddenCopy()), that look alike
  * (colourOverlap() of kMinLoosePairColourOverlap at least), and that are not the two ends of
  * one box hidden in the middle (CopyCutter::endsOfOneBox()), make a model: the hidden copy
  * with its box completed. Each object takes the first such partner, in the order of
  * `founders`.
  */
void
pairHiddenCopies (const FreeObjects& objects,
                  const std::vector<std::size_t>& founders,
                  const CopyCutter& cutter,
                  const KeypointSurface& surface,
                  CopyPlacement& placement,
                  std::vector<bool>& used)
{
  for (const std::size_t whole : founders)
    for (const std::size_t part : founders) {
      if (used[whole] || used[part] || part == whole)
        continue;
      const FreeObjects hidden =
          cutter.hiddenCopy (objects[part], objects[whole].extent.size);
      if (hidden.empty() ||
          detail::colourOverlap (surface, objects[whole], objects[part]) <
              detail::kMinLoosePairColourOverlap ||
          cutter.endsOfOneBox (objects[whole], objects[part]))
        continue;
      used[whole] = used[part] = true;
      placement.addModelOfCopies ({objects[whole], hidden.front()});
    }
}

} // namespace

std::string
SizeInstanceSearch::inputProblem (const ObjectModels& models) const
{
  if (std::string problem = measurementProblem (models); !problem.empty())
    return problem;
  if (!descriptors_ || descriptors_->size() != keypoints_->size())
    return "the descriptors are not one per keypoint";
  if (min_keypoints_ < 1)
    return "one keypoint at least must make an instance";
  if (!(max_surrounded_share_ >= 0.0f && max_surrounded_share_ <= 1.0f) ||
      !(min_model_edge_ >= 0.0f) || !std::isfinite (min_model_edge_))
    return "the surrounded share must be in [0, 1] and the shortest edge finite and >= "
           "0";
  return "";
}

bool
SizeInstanceSearch::search (ObjectModels& models, std::size_t& found) const
{
  found = 0;
  const std::string problem = inputProblem (models);
  if (!problem.empty()) {
    PCL_ERROR ("[mid::SizeInstanceSearch::search] %s.\n", problem.c_str());
    return false;
  }
  if (models.empty() && !discover_models_)
    return true;
  const auto& organized = *surface_.organized;
  Eigen::Vector4f plane;
  if (!fitPlane (plane))
    return true;
  const SizeAgreement agree = agreement();
  std::vector<InstanceExtents> extents;
  if (!measureBoxes (models, plane, extents))
    return false;
  ModelSizes sizes;
  modelSizesOfBoxes (models, extents, agree, min_agreeing_, sizes);
  if (!discover_models_ &&
      std::none_of (sizes.begin(), sizes.end(), [] (const ModelSize& size) {
        return size.valid;
      }))
    return true;

  // The objects as they lie, and those beside the found copies of a measured model, grown
  // with the points inside those copies' boxes left out.
  const detail::ObjectSeeds seeds =
      detail::objectSeeds (models, surface_.keypoint_pixels);
  const detail::Growth growth{max_step_, max_radius_, plane_tolerance_};
  FreeObjects free_objects, beside_found, boxing_found;
  const auto boxes = detail::foundCopyBoxes (models, sizes);
  if (!detail::freeObjects (organized,
                            organized,
                            plane,
                            seeds,
                            *keypoints_,
                            growth,
                            min_keypoints_,
                            free_objects,
                            &boxing_found) ||
      (!boxes.empty() &&
       !detail::freeObjects (detail::withoutFoundCopies (organized, boxes),
                             organized,
                             plane,
                             seeds,
                             *keypoints_,
                             growth,
                             min_keypoints_,
                             beside_found)))
    return false;

  // A copy of a model's size joins it (measured beside the found copies first), unless one of
  // its keypoints went to another copy already or the model has a copy there.
  const CopyCutter cutter (organized,
                           plane,
                           *keypoints_,
                           surface_.keypoint_pixels,
                           agree,
                           min_keypoints_,
                           min_model_edge_);
  CopyPlacement placement (models, sizes, extents, agree, *keypoints_, *descriptors_);
  for (const FreeObject& object : beside_found)
    joinModelOrCutIntoCopies (object, sizes, cutter, min_keypoints_, placement);
  // An object of no model's size, of the shortest edge asked for (and standing alone when
  // asked), may found a model with others of its size; the other objects of no model's size
  // may be copies of it touching each other flush.
  std::vector<std::size_t> founders, others;
  for (std::size_t o = 0; o < free_objects.size(); ++o) {
    const FreeObject& object = free_objects[o];
    if (joinModelOrCutIntoCopies (object, sizes, cutter, min_keypoints_, placement) >=
            0 ||
        !discover_models_ || !placement.untaken (object))
      continue;
    if (object.extent.size.minCoeff() >= min_model_edge_ &&
        (max_surrounded_share_ >= 1.0f ||
         detail::surroundedShare (
             organized, plane, object.extent, 2.0f * plane_tolerance_) <=
             max_surrounded_share_))
      founders.push_back (o);
    else
      others.push_back (o);
  }
  std::vector<std::size_t> candidates = founders;
  candidates.insert (candidates.end(), others.begin(), others.end());
  std::vector<bool> used (free_objects.size(), false);
  discoverModelsOfCopies (free_objects,
                          founders,
                          candidates,
                          cutter,
                          agree,
                          surface_,
                          min_keypoints_,
                          placement,
                          used);
  pairHiddenCopies (free_objects, founders, cutter, surface_, placement, used);
  // An object that is no rectangle has a box that may reach around a found copy: its parts'
  // boxes must not.
  for (const FreeObject& object : boxing_found) {
    if (!discover_models_ || !placement.untaken (object))
      continue;
    const FreeObjects copies = cutter.copiesOfItsOutline (object);
    if (copies.size() < 2 ||
        std::any_of (copies.begin(), copies.end(), [&] (const FreeObject& copy) {
          return detail::boxHoldsObserved (
              copy.extent, *keypoints_, seeds.observed, detail::kBoxMargin);
        }))
      continue;
    placement.addCopies (copies);
  }
  found = placement.found();
  return true;
}

} // namespace mid
