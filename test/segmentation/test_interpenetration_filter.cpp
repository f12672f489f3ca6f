// InterpenetrationFilter on rendered boxes resting on a table at known poses: a second instance
// of a model on one box, moved by less or more than the box's shortest edge.
#include "resting_boxes.h"

#include <mid/segmentation/interpenetration_filter.h>

#include <gtest/gtest.h>

#include <limits>

namespace {

using Boxes = mid::test::RestingBoxes;

mid::InterpenetrationFilter
filterFor (const Boxes& scene)
{
  return mid::test::measuringStep<mid::InterpenetrationFilter> (scene);
}

/** Split an instance's observations: it keeps the first `kept`, and the returned instance,
  * at its pose moved by `shift` (metres, along the camera's x axis, parallel to the table),
  * holds the rest.
  */
mid::ModelInstance
splitOff (mid::ModelInstance& instance, std::size_t kept, float shift)
{
  mid::ModelInstance second = instance;
  const auto at = static_cast<std::ptrdiff_t> (kept);
  instance.keypoints.resize (kept);
  instance.landmarks.resize (kept);
  second.keypoints.erase (second.keypoints.begin(), second.keypoints.begin() + at);
  second.landmarks.erase (second.landmarks.begin(), second.landmarks.begin() + at);
  second.pose.topRightCorner<3, 1>() += Eigen::Vector3f (shift, 0.0f, 0.0f);
  return second;
}

/** The model of boxes 0 to 3 at their true poses, box 0's instance holding the first 60 % of
  * its observations, and a fifth instance holding the rest at box 0's pose moved by `shift`.
  */
mid::ObjectModel
withSecondInstanceOnBox0 (const Boxes& scene, float shift)
{
  mid::ObjectModel model = scene.modelOf ({0, 1, 2, 3});
  const std::size_t kept = model.instances[0].keypoints.size() * 6 / 10;
  model.instances.push_back (splitOff (model.instances[0], kept, shift));
  return model;
}

} // namespace

TEST (InterpenetrationFilter, RemovesAnInstanceCloserToAnotherThanTheShortestEdge)
{
  // The boxes' shortest edge is 0.04 m: a second instance 0.028 m (0.7 edges) from box 0's
  // interpenetrates it; one 0.036 m (0.9 edges) away does not, at the default 0.8.
  const Boxes scene (mid::test::fourBoxes());
  const mid::InterpenetrationFilter filter = filterFor (scene);
  for (const float shift : {0.028f, -0.028f}) {
    mid::ObjectModels models = {withSecondInstanceOnBox0 (scene, shift)};
    std::size_t removed = 0;
    ASSERT_TRUE (filter.filter (models, removed));
    EXPECT_EQ (removed, 1u);
    ASSERT_EQ (models.size(), 1u);
    ASSERT_EQ (models[0].instances.size(), 4u);
    for (int b = 0; b < 4; ++b) // the true instances stay, in their order
      EXPECT_EQ (
          scene.boxOf (models[0].instances[static_cast<std::size_t> (b)].keypoints), b);
  }
  for (const float shift : {0.036f, -0.036f}) {
    mid::ObjectModels models = {withSecondInstanceOnBox0 (scene, shift)};
    std::size_t removed = 0;
    ASSERT_TRUE (filter.filter (models, removed));
    EXPECT_EQ (removed, 0u);
    ASSERT_EQ (models.size(), 1u);
    EXPECT_EQ (models[0].instances.size(), 5u);
  }
}

TEST (InterpenetrationFilter,
      RemovesAModelLeftWithOneCopyWhenOneMeasuredCopyGivesItsSize)
{
  // Boxes 0 and 1 make one model; the other model's two instances lie on box 2, each measured
  // on the part of its top that its keypoints reach first, so no two agree on a size.
  const Boxes scene (mid::test::fourBoxes());
  mid::ObjectModel on_box_2 = scene.modelOf ({2});
  const std::size_t kept = on_box_2.instances[0].keypoints.size() / 2 + 1;
  on_box_2.instances.push_back (splitOff (on_box_2.instances[0], kept, 0.01f));
  const mid::ObjectModels original = {scene.modelOf ({0, 1}), on_box_2};

  // By default two measured copies must agree on the size: nothing is removed.
  mid::InterpenetrationFilter filter = filterFor (scene);
  EXPECT_EQ (filter.getMinAgreeing(), 2);
  mid::ObjectModels models = original;
  std::size_t removed = 0;
  ASSERT_TRUE (filter.filter (models, removed));
  EXPECT_EQ (removed, 0u);
  EXPECT_EQ (models.size(), 2u);

  // With one enough, the second instance goes, and the model of one copy with it.
  filter.setMinAgreeing (1);
  models = original;
  ASSERT_TRUE (filter.filter (models, removed));
  EXPECT_EQ (removed, 2u);
  ASSERT_EQ (models.size(), 1u);
  EXPECT_EQ (models[0].instances.size(), 2u);
}

TEST (InterpenetrationFilter, RefusesBadInputAndLeavesTheModels)
{
  const Boxes scene (mid::test::fourBoxes());
  const mid::ObjectModels original = {withSecondInstanceOnBox0 (scene, 0.01f)};
  const auto refuses = [&] (const mid::InterpenetrationFilter& filter) {
    mid::ObjectModels models = original;
    std::size_t removed = std::numeric_limits<std::size_t>::max();
    EXPECT_FALSE (filter.filter (models, removed));
    EXPECT_EQ (removed, 0u);
    ASSERT_EQ (models.size(), 1u);
    EXPECT_EQ (models[0].instances.size(), original[0].instances.size());
  };
  for (const float ratio : {-0.1f, 1.5f, std::numeric_limits<float>::quiet_NaN()}) {
    mid::InterpenetrationFilter filter = filterFor (scene);
    filter.setMaxCentreDistance (ratio);
    refuses (filter);
  }
  mid::InterpenetrationFilter none_agreeing = filterFor (scene);
  none_agreeing.setMinAgreeing (0);
  refuses (none_agreeing);
  mid::InterpenetrationFilter no_keypoints = filterFor (scene);
  no_keypoints.setInputKeypoints (nullptr);
  refuses (no_keypoints);
}
