// Seed 000 §2.3, "New end position": MC_MoveAbsolute 0 → 3000 mm at V 2000 mm/s (braking from
// 1.5 s at 2500 mm, at rest at 2.0 s), then MC_NewPos.
#include <algorithm>
#include <string>

#include "fb/mc_move_absolute.hpp"
#include "fb/mc_new_pos.hpp"
#include "scenarios.hpp"

namespace gallery {
namespace {

Figure new_pos(const std::filesystem::path& out, const std::string& name, const std::string& title,
               double at, double new_end, bool reverses) {
  Rig rig(seed_axis(), 6.0);
  rig.check_limits({2000.0, 5000.0, 5000.0, 50000.0});
  fb::MC_MoveAbsolute move;
  fb::MC_NewPos change;
  move.Position = 3000.0;
  move.Velocity = 2000.0;
  change.NewPos = new_end;
  double min_velocity = 0.0;
  bool change_done = false;
  rig.run(
      [&](Rig& r) {
        move.Execute = r.power().Status;
        move(r.axis());
        r.watch(move, "MC_MoveAbsolute");
        change.Execute = r.time() >= at;
        change(r.axis());
        r.watch(change, "MC_NewPos");
        change_done = change_done || change.Done;
        min_velocity = std::min(min_velocity, r.axis().NcToPlc.SetVelo);
      },
      // The positioning ends Done on whichever block carries the job at the end.
      [&] {
        return (move.Done || change_done) && rig.at_rest() && rig.axis().NcToPlc.SetPos == new_end;
      });
  rig.expect(rig.axis().NcToPlc.SetPos == new_end, "ends exactly at the new end position");
  // The NC answers MC_NewPos once it took the new end position over; the positioning keeps
  // its command, so MC_MoveAbsolute shows Done at the new end.
  rig.expect(change_done, "MC_NewPos Done");
  rig.expect(move.Done, "MC_MoveAbsolute Done at the new end position");
  rig.expect(reverses ? min_velocity < 0.0 : min_velocity == 0.0,
             reverses ? "reverses and returns" : "never reverses");
  return rig.write(out, name, title);
}

}  // namespace

void new_end_position(const std::filesystem::path& out, Figures& figures) {
  figures.push_back(new_pos(out, "new_pos_stop_phase",
                            "New end position 5000 mm at 1.7 s, during the stop phase of "
                            "0 \u2192 3000 mm (V 2000 mm/s)",
                            1.7, 5000.0, false));
  figures.push_back(new_pos(out, "new_pos_reversal",
                            "New end position 2000 mm at 1.2 s (at 1900 mm, 2000 mm/s) of "
                            "0 \u2192 3000 mm: stop and return",
                            1.2, 2000.0, true));
}

}  // namespace gallery
