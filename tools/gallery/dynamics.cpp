// Seed 000 §2.1, "Dynamics I–III": one positioning from 0 mm per figure, with the figure's
// A+, A-, J and V given to MC_MoveAbsolute (the seed's R is the jerk J).
#include <string>

#include "fb/mc_move_absolute.hpp"
#include "scenarios.hpp"

namespace gallery {
namespace {

struct Case {
  const char* name;
  const char* label;
  double acceleration, deceleration, jerk, velocity, target;
};

Figure positioning(const std::filesystem::path& out, const Case& c) {
  Rig rig(seed_axis(), 3.0);
  rig.check_limits({c.velocity, c.acceleration, c.deceleration, c.jerk});
  fb::MC_MoveAbsolute move;
  move.Position = c.target;
  move.Velocity = c.velocity;
  move.Acceleration = c.acceleration;
  move.Deceleration = c.deceleration;
  move.Jerk = c.jerk;
  rig.run(
      [&](Rig& r) {
        move.Execute = r.power().Status;
        move(r.axis());
        r.watch(move, "MC_MoveAbsolute");
      },
      [&] { return move.Done; });
  rig.expect(rig.axis().NcToPlc.SetPos == c.target, "ends exactly at the target");
  const std::string title = std::string(c.label) + ": A+ " + num(c.acceleration) + ", A- " +
                            num(c.deceleration) + " mm/s\u00b2, J " + num(c.jerk) +
                            " mm/s\u00b3, V " + num(c.velocity) + " mm/s, 0 \u2192 " +
                            num(c.target) + " mm";
  return rig.write(out, c.name, title);
}

}  // namespace

void dynamics(const std::filesystem::path& out, Figures& figures) {
  const Case cases[] = {
      {"dynamics_1_1", "Dynamics 1.1", 5000.0, 5000.0, 50000.0, 2000.0, 1000.0},
      {"dynamics_1_2", "Dynamics 1.2", 5000.0, 10000.0, 50000.0, 2000.0, 1000.0},
      {"dynamics_1_3", "Dynamics 1.3", 15000.0, 15000.0, 50000.0, 2000.0, 1000.0},
      {"dynamics_2_1", "Dynamics 2.1", 5000.0, 5000.0, 20000.0, 2000.0, 1000.0},
      {"dynamics_2_2", "Dynamics 2.2", 5000.0, 5000.0, 50000.0, 2000.0, 1000.0},
      {"dynamics_2_3", "Dynamics 2.3", 5000.0, 5000.0, 100000.0, 2000.0, 1000.0},
      {"dynamics_3_1", "Dynamics 3.1", 5000.0, 5000.0, 50000.0, 1500.0, 800.0},
      {"dynamics_3_2", "Dynamics 3.2", 5000.0, 5000.0, 50000.0, 1750.0, 800.0},
      {"dynamics_3_3", "Dynamics 3.3", 5000.0, 5000.0, 50000.0, 2000.0, 800.0},
  };
  for (const Case& c : cases)
    figures.push_back(positioning(out, c));
}

}  // namespace gallery
