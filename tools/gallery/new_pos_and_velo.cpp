// Seed 000 §2.4, "New velocity and new end position", cases 1–6 in the positive direction:
// MC_MoveAbsolute 0 → 3000 mm at VOld = 2000 mm/s, then MC_NewPosAndVelo with EPos, VNew =
// 1000 mm/s and APos placed around the position Pos the axis has when the block fires.
#include <algorithm>
#include <string>

#include "fb/mc_move_absolute.hpp"
#include "fb/mc_new_pos_and_velo.hpp"
#include "scenarios.hpp"

namespace gallery {
namespace {

constexpr double kOld = 2000.0;  // mm/s, VOld
constexpr double kNew = 1000.0;  // mm/s, VNew

struct Case {
  const char* name;
  const char* rule;   // the seed's relation, in the direction of travel
  double at;          // s, when the block fires
  double pos;         // mm, Pos then (0.5 s ramp to 2000 mm/s covers 500 mm)
  double apos, epos;  // mm
  bool reverses;      // the axis stops and returns
  double late;        // s, a time in a later cruise …
  double cruise;      // mm/s, … and the set velocity then
};

Figure npv(const std::filesystem::path& out, const Case& c) {
  Rig rig(seed_axis(), 8.0);
  rig.check_limits({kOld, 5000.0, 5000.0, 50000.0});
  fb::MC_MoveAbsolute move;
  fb::MC_NewPosAndVelo change;
  move.Position = 3000.0;
  move.Velocity = kOld;
  change.NewPos = c.epos;
  change.NewVelo = kNew;
  change.ActivationPos = c.apos;
  double min_velocity = 0.0;
  double late_velocity = 0.0;
  bool change_done = false;
  rig.run(
      [&](Rig& r) {
        move.Execute = r.power().Status;
        move(r.axis());
        r.watch(move, "MC_MoveAbsolute");
        change.Execute = r.time() >= c.at;
        change(r.axis());
        r.watch(change, "MC_NewPosAndVelo");
        change_done = change_done || change.Done;
        const double v = r.axis().NcToPlc.SetVelo;
        min_velocity = std::min(min_velocity, v);
        if (r.time() <= c.late) late_velocity = v;
      },
      [&] {
        return (move.Done || change_done) && rig.at_rest() && rig.axis().NcToPlc.SetPos == c.epos;
      });
  rig.expect(rig.axis().NcToPlc.SetPos == c.epos, "ends exactly at EPos");
  rig.expect(change_done, "MC_NewPosAndVelo Done");
  rig.expect(move.Done, "MC_MoveAbsolute Done at EPos");
  rig.expect(c.reverses ? min_velocity < 0.0 : min_velocity == 0.0,
             c.reverses ? "stops and returns" : "never reverses");
  rig.expect_near(late_velocity, c.cruise, 1e-6, "set velocity at " + num(c.late) + " s");
  const std::string title = std::string("NewPosAndVelo ") + c.rule + ": Pos " + num(c.pos) +
                            ", APos " + num(c.apos) + ", EPos " + num(c.epos) + ", VNew " +
                            num(kNew);
  return rig.write(out, c.name, title);
}

}  // namespace

void new_velocity_and_end_position(const std::filesystem::path& out, Figures& figures) {
  // Pos is where the axis is when the block fires (a 0.5 s ramp to 2000 mm/s covers 500 mm).
  const Case cases[] = {
      // 1: VNew from APos on (crossed at about 1.25 s), to EPos.
      {"npv_case1", "case 1 (Pos \u2264 APos \u2264 EPos)", 0.75, 1000.0, 2000.0, 4000.0, false,
       2.0, kNew},
      // 2: VNew at once.
      {"npv_case2", "case 2 (APos \u2264 Pos \u2264 EPos)", 0.75, 1000.0, 500.0, 4000.0, false, 1.5,
       kNew},
      // 3: stop (at 2500 mm), return with VOld.
      {"npv_case3", "case 3 (APos \u2264 EPos \u2264 Pos)", 1.25, 2000.0, 500.0, 1000.0, true, 2.35,
       -kOld},
      // 4: only the new end position; VOld stays.
      {"npv_case4", "case 4 (Pos \u2264 EPos \u2264 APos)", 0.75, 1000.0, 3000.0, 2500.0, false,
       1.0, kOld},
      // 5: stop (at 2500 mm), return with VOld, VNew once APos is crossed on the way back.
      {"npv_case5", "case 5 (EPos \u2264 APos \u2264 Pos)", 1.25, 2000.0, 1500.0, 0.0, true, 3.2,
       -kNew},
      // 6: stop (at 2000 mm), return with VOld.
      {"npv_case6", "case 6 (EPos \u2264 Pos \u2264 APos)", 1.0, 1500.0, 2500.0, 500.0, true, 2.1,
       -kOld},
  };
  for (const Case& c : cases)
    figures.push_back(npv(out, c));
}

}  // namespace gallery
