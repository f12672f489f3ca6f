#pragma once

#include <mid/registration/object_model.h>

#include <algorithm>
#include <iterator>

namespace mid {
namespace test {

/** \brief Give `model` one descriptor per landmark, in order, each carrying its landmark's index
  * in its first bin (the others zero), so that a test can check that renumbering the landmarks
  * kept every descriptor with its own.
  */
inline void
describeLandmarksByNumber (ObjectModel& model)
{
  for (std::size_t l = 0; l < model.landmarks.size(); ++l) {
    SIFTDescriptor descriptor;
    std::fill (
        std::begin (descriptor.histogram), std::end (descriptor.histogram), 0.0f);
    descriptor.histogram[0] = static_cast<float> (l);
    model.descriptors.push_back (descriptor);
    model.descriptor_landmarks.push_back (static_cast<int> (l));
  }
}

} // namespace test
} // namespace mid
