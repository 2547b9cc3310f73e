// Seed 000 §2.2, "Stop" and "Emergency stop": MC_Stop during 0 → 5000 mm at V 2000 mm/s, at
// 1.0 s (cruising at 2000 mm/s from 1500 mm). Its Deceleration and Jerk are adopted only when
// both are larger than the running motion's (5000 mm/s², 50000 mm/s³).
#include <string>

#include "fb/mc_move_absolute.hpp"
#include "fb/mc_stop.hpp"
#include "scenarios.hpp"

namespace gallery {
namespace {

Figure stop_at_one_second(const std::filesystem::path& out, const std::string& name,
                          const std::string& title, double deceleration, double jerk,
                          const CheckedLimits& limits, double expected_distance) {
  Rig rig(seed_axis(), 4.0);
  rig.check_limits(limits);
  fb::MC_MoveAbsolute move;
  fb::MC_Stop stop;
  move.Position = 5000.0;
  move.Velocity = 2000.0;
  stop.Deceleration = deceleration;
  stop.Jerk = jerk;
  double stop_from = -1.0;  // mm, set position published just before the stop was posted
  rig.run(
      [&](Rig& r) {
        move.Execute = r.power().Status;
        move(r.axis());
        r.watch(move, "MC_MoveAbsolute");
        stop.Execute = r.time() >= 1.0;
        stop(r.axis());
        r.watch(stop, "MC_Stop");
        if (stop.Busy && stop_from < 0.0) stop_from = r.axis().NcToPlc.SetPos;
      },
      [&] { return stop.Done; });
  rig.expect(move.CommandAborted, "MC_MoveAbsolute shows CommandAborted");
  // The NC takes the stop one cycle after the position read: up to 2 mm at 2000 mm/s.
  rig.expect_near(rig.axis().NcToPlc.SetPos - stop_from, expected_distance, 2.5,
                  "braking distance");
  return rig.write(out, name, title);
}

}  // namespace

void stops(const std::filesystem::path& out, Figures& figures) {
  // Both larger: 2000 mm/s comes down in 2000/10000 + 10000/100000 = 0.3 s over 300 mm.
  figures.push_back(
      stop_at_one_second(out, "stop_emergency_adopted",
                         "MC_Stop at 1.0 s, Deceleration 10000, Jerk 100000: both larger, adopted",
                         10000.0, 100000.0, {2000.0, 5000.0, 10000.0, 100000.0}, 300.0));
  // Jerk smaller than the running motion's: the running 5000 / 50000 stop it, 0.5 s over 500 mm.
  figures.push_back(stop_at_one_second(
      out, "stop_emergency_not_adopted",
      "MC_Stop at 1.0 s, Deceleration 10000, Jerk 20000: not both larger, not adopted", 10000.0,
      20000.0, {2000.0, 5000.0, 5000.0, 50000.0}, 500.0));
}

}  // namespace gallery
