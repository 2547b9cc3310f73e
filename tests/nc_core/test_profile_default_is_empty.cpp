// A default-constructed Profile is empty (issue 17: its header fields and segment count are set by
// its default constructor, no longer by default member initializers, so that the planners' own
// constructor can leave them to the profile writer). Built in storage that holds garbage first, so
// that a field the constructor forgot shows as garbage: no segments, duration 0, ok(), not holding
// a velocity, the start and final states at rest at 0, and at() / jerk_at() give that rest state
// everywhere. Profile::failure(code) is the same with its code, and a planned profile assigned
// an empty one is empty again.
#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <limits>
#include <new>

#include "nc_core/profile.hpp"

namespace {

using nc::ErrorCode;
using nc::KinematicState;
using nc::Profile;

bool at_rest_at_zero(const KinematicState& s) {
  return s.p == 0.0 && s.v == 0.0 && s.a == 0.0;
}

// What an empty profile with error `code` shows through the public interface.
void check_empty(const Profile& p, ErrorCode code) {
  CHECK(p.error() == code);
  CHECK(p.ok() == (code == ErrorCode::kNone));
  CHECK(p.segment_count() == 0);
  CHECK(p.duration() == 0.0);
  CHECK_FALSE(p.holds_velocity());
  CHECK(at_rest_at_zero(p.start_state()));
  CHECK(at_rest_at_zero(p.final_state()));
  for (const double t : {-1.0, 0.0, 0.5, 1e9}) {
    CHECK(at_rest_at_zero(p.at(t)));
    CHECK(p.jerk_at(t) == 0.0);
  }
}

}  // namespace

TEST_CASE("a default Profile is empty whatever its storage held before") {
  for (const int garbage : {0x00, 0x7F, 0xA5, 0xFF}) {
    alignas(Profile) unsigned char storage[sizeof(Profile)];
    std::memset(storage, garbage, sizeof storage);
    const Profile* p = ::new (static_cast<void*>(storage)) Profile();
    INFO("storage filled with " << garbage);
    check_empty(*p, ErrorCode::kNone);
    p->~Profile();
  }
}

TEST_CASE("Profile::failure is empty with its code whatever its storage held before") {
  alignas(Profile) unsigned char storage[sizeof(Profile)];
  std::memset(storage, 0xA5, sizeof storage);
  const Profile* p =
      ::new (static_cast<void*>(storage)) Profile(Profile::failure(ErrorCode::kJerkNotAllowed));
  check_empty(*p, ErrorCode::kJerkNotAllowed);
  p->~Profile();
}

TEST_CASE("a planned profile assigned an empty one is empty again") {
  const nc::Limits limits{100.0, 1000.0, 800.0, 20000.0};
  Profile p = nc::plan_position({0.0, 3.0, -40.0}, 12.5, limits);
  REQUIRE(p.ok());
  REQUIRE(p.segment_count() > 0);
  REQUIRE(p.duration() > 0.0);
  REQUIRE(p.final_state().p == 12.5);
  p = Profile();
  check_empty(p, ErrorCode::kNone);

  Profile v = nc::plan_velocity({1.0, 2.0, 0.0}, -50.0, limits);
  REQUIRE(v.holds_velocity());
  v = Profile();
  check_empty(v, ErrorCode::kNone);
}
