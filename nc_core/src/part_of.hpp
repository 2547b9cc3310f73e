// The base of a class that is a part of a larger object and works on that object's state for one
// call (the parts of a servo axis over AxisCore, the HLI stage's parts over HliState): made where
// it is needed, owning nothing, so that a part is a class of its own rather than more member
// functions on its owner.
#pragma once

namespace nc {

template <class State>
class PartOf {
 public:
  explicit PartOf(State& state) noexcept : s_(state) {}

 protected:
  State& s_;
};

}  // namespace nc
