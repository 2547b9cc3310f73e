// Seed 000 §2.1, modulo starts on an axis with modulo factor 360 (units ° here, drawn as mm):
// the sign of the modulo position gives the direction, positions at or above the factor add
// whole turns, and MC_MoveModulo's Direction picks the way round.
#include <string>
#include <vector>

#include "fb/mc_move_modulo.hpp"
#include "scenarios.hpp"

namespace gallery {
namespace {

constexpr double kVelocity = 360.0;       // °/s
constexpr double kAcceleration = 1800.0;  // °/s²
constexpr double kJerk = 18000.0;         // °/s³

nc::AxisConfig modulo_axis() {
  nc::AxisConfig c = seed_axis();
  c.modulo_factor = 360.0;
  return c;
}

struct Step {
  double position;
  fb::MC_Direction direction;
  double end;  // absolute set position expected at the end
};

// Plays the steps one after the other with one MC_MoveModulo, 0.2 s apart.
Figure play(const std::filesystem::path& out, const std::string& name, const std::string& title,
            const std::vector<Step>& steps) {
  Rig rig(modulo_axis(), 12.0);
  rig.check_limits({kVelocity, kAcceleration, kAcceleration, kJerk});
  fb::MC_MoveModulo move;
  move.Velocity = kVelocity;
  move.Acceleration = kAcceleration;
  move.Deceleration = kAcceleration;
  move.Jerk = kJerk;
  std::size_t step = 0;
  double pause_until = 0.0;
  std::vector<double> ends;
  rig.run(
      [&](Rig& r) {
        if (step < steps.size() && r.power().Status && r.time() >= pause_until) {
          move.Position = steps[step].position;
          move.Direction = steps[step].direction;
          move.Execute = true;
        }
        move(r.axis());
        r.watch(move, "MC_MoveModulo");
        if (move.Done && move.Execute) {
          ends.push_back(r.axis().NcToPlc.SetPos);
          move.Execute = false;
          ++step;
          pause_until = r.time() + 0.2;
        }
      },
      [&] { return step == steps.size(); }, 0.2);
  rig.expect(ends.size() == steps.size(), "every step ends Done");
  for (std::size_t i = 0; i < ends.size() && i < steps.size(); ++i) {
    rig.expect_near(ends[i], steps[i].end, 1e-9, "step " + std::to_string(i + 1) + " ends at");
  }
  return rig.write(out, name, title, Extra::kModuloSetPos);
}

}  // namespace

void modulo(const std::filesystem::path& out, Figures& figures) {
  // From 0: 540 = one extra turn, ends at 540 (modulo 180).
  figures.push_back(play(out, "modulo_540",
                         "MC_MoveModulo Position 540, modulo factor 360, from 0: one extra "
                         "turn, ends at modulo 180",
                         {{540.0, fb::MC_Positive_Direction, 540.0}}));
  // 90 positive; 0.0 positive (a full way round to 360); 350 the shortest way (back 10);
  // 10 the shortest way (forward across 0/360, +20); 270 negative (back 100).
  figures.push_back(
      play(out, "modulo_directions",
           "MC_MoveModulo: 90 positive, 0.0 positive, 350 shortest, 10 shortest (across 0/360), "
           "270 negative",
           {{90.0, fb::MC_Positive_Direction, 90.0},
            {0.0, fb::MC_Positive_Direction, 360.0},
            {350.0, fb::MC_Shortest_Way, 350.0},
            {10.0, fb::MC_Shortest_Way, 370.0},
            {270.0, fb::MC_Negative_Direction, 270.0}}));
}

}  // namespace gallery
