// Continuous motion (SPEC B1, issue 4): MC_MoveVelocity 1500 mm/s positive; at 1.5 s 500 mm/s
// in the current direction; at 2.5 s 1000 mm/s negative; MC_Halt at 3.5 s ends it.
#include <string>

#include "fb/mc_halt.hpp"
#include "fb/mc_move_velocity.hpp"
#include "scenarios.hpp"

namespace gallery {

void continuous_motion(const std::filesystem::path& out, Figures& figures) {
  Rig rig(seed_axis(), 6.0);
  rig.check_limits({1500.0, 5000.0, 5000.0, 50000.0});
  fb::MC_MoveVelocity fast;
  fb::MC_MoveVelocity slow;
  fb::MC_MoveVelocity back;
  fb::MC_Halt halt;
  fast.Velocity = 1500.0;
  fast.Direction = fb::MC_Positive_Direction;
  slow.Velocity = 500.0;
  slow.Direction = fb::MC_Current_Direction;
  back.Velocity = 1000.0;
  back.Direction = fb::MC_Negative_Direction;
  bool fast_in_velocity = false;
  bool slow_in_velocity = false;
  bool back_in_velocity = false;
  rig.run(
      [&](Rig& r) {
        const double t = r.time();
        fast.Execute = r.power().Status;
        fast(r.axis());
        slow.Execute = t >= 1.5;
        slow(r.axis());
        back.Execute = t >= 2.5;
        back(r.axis());
        halt.Execute = t >= 3.5;
        halt(r.axis());
        r.watch(fast, "MC_MoveVelocity 1500");
        r.watch(slow, "MC_MoveVelocity 500 current");
        r.watch(back, "MC_MoveVelocity 1000 negative");
        r.watch(halt, "MC_Halt");
        fast_in_velocity = fast_in_velocity || fast.InVelocity;
        slow_in_velocity = slow_in_velocity || (slow.InVelocity && r.axis().NcToPlc.SetVelo > 0.0);
        back_in_velocity = back_in_velocity || (back.InVelocity && r.axis().NcToPlc.SetVelo < 0.0);
      },
      [&] { return halt.Done; });
  rig.expect(fast_in_velocity, "InVelocity at 1500 mm/s");
  rig.expect(slow_in_velocity, "InVelocity at 500 mm/s, still positive");
  rig.expect(back_in_velocity, "InVelocity at 1000 mm/s negative");
  rig.expect(back.CommandAborted, "the halt aborts the velocity job");
  rig.expect(rig.at_rest(), "at rest after the halt");
  figures.push_back(rig.write(out, "continuous_motion",
                              "MC_MoveVelocity 1500 \u2192 500 current (1.5 s) \u2192 1000 "
                              "negative (2.5 s) mm/s, MC_Halt at 3.5 s"));
}

}  // namespace gallery
