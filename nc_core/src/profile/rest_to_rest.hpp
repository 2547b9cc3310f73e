// The rest-to-rest fast path of plan_position in closed form (internal).
#pragma once

#include "profile/kinematics.hpp"

namespace nc::detail {

// Pieces of the time-optimal motion over `distance` > 0 from rest to rest (seed 000 §2.1's 7
// phases); returns their number (at most 7) and sets `n_up` to the number of the acceleration
// pieces. The same profile as the general push-then-stop path.
int rest_to_rest(double distance, double velocity, const Bounds& bounds, Piece* out,
                 int& n_up) noexcept;

}  // namespace nc::detail
