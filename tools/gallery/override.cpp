// Seed 000 §2.2, "Override": the override changes the velocity level at once, as fast as A+, A-
// and J allow, with no undershoot; a start at 0 % waits; 0 % in motion rests on the path. Each
// figure: MC_MoveAbsolute 0 → 5000 mm at V 2000 mm/s, MC_SetOverride changing VelFactor at
// the times the title names.
#include <algorithm>
#include <functional>
#include <string>

#include "fb/mc_move_absolute.hpp"
#include "fb/mc_set_override.hpp"
#include "scenarios.hpp"

namespace gallery {
namespace {

constexpr double kTarget = 5000.0;    // mm
constexpr double kVelocity = 2000.0;  // mm/s

// What the run saw of the set velocity inside one time window.
struct Window {
  double from, to;
  double min = 1e300, max = -1e300, last = 0.0;
  void see(double t, double v) {
    if (t < from || t > to) return;
    min = std::min(min, v);
    max = std::max(max, v);
    last = v;
  }
};

// Runs the move with VelFactor = factor(t); returns the figure after the common checks.
Figure run(const std::filesystem::path& out, const std::string& name, const std::string& title,
           const std::function<double(double)>& factor, std::vector<Window>& windows) {
  Rig rig(seed_axis(), 12.0);
  rig.check_limits({kVelocity, 5000.0, 5000.0, 50000.0});
  fb::MC_MoveAbsolute move;
  fb::MC_SetOverride set;
  move.Position = kTarget;
  move.Velocity = kVelocity;
  rig.run(
      [&](Rig& r) {
        set.Enable = true;
        set.VelFactor = factor(r.time());
        set(r.axis());
        r.watch(set, "MC_SetOverride");
        move.Execute = r.power().Status;
        move(r.axis());
        r.watch(move, "MC_MoveAbsolute");
        for (Window& w : windows)
          w.see(r.time(), r.axis().NcToPlc.SetVelo);
      },
      [&] { return move.Done; });
  rig.expect(rig.axis().NcToPlc.SetPos == kTarget, "ends exactly at 5000 mm");
  Figure f = rig.write(out, name, title, Extra::kOverride);
  return f;
}

void expect(Figure& f, bool ok, const std::string& what) {
  if (!ok) f.problems.push_back(what);
}

}  // namespace

void override_changes(const std::filesystem::path& out, Figures& figures) {
  {
    // 100 % → 75 % at 1.0 s → 100 % at 2.0 s: a plateau at 1500 mm/s reached from above
    // without going under it, then back to 2000 mm/s.
    std::vector<Window> w = {{1.0, 2.0}, {1.8, 2.0}, {2.4, 2.6}};
    Figure f = run(
        out, "override_100_75_100",
        "Override 100 % \u2192 75 % (1.0 s) \u2192 100 % (2.0 s); V 2000 mm/s, 0 \u2192 5000 mm",
        [](double t) { return t < 1.0   ? 1.0
                              : t < 2.0 ? 0.75
                                        : 1.0; }, w);
    expect(f, w[0].min >= 1500.0 - 1e-6, "no undershoot below 1500 mm/s at 75 %");
    expect(f, w[1].last > 1500.0 - 1e-6 && w[1].last < 1500.0 + 1e-6, "plateau at 1500 mm/s");
    expect(f, w[2].last > 2000.0 - 1e-6, "back to 2000 mm/s at 100 %");
    figures.push_back(f);
  }
  {
    // Start at 20 % (400 mm/s), 100 % from 1.5 s.
    std::vector<Window> w = {{1.3, 1.5}, {2.5, 2.6}};
    Figure f = run(
        out, "override_20_100", "Override 20 % \u2192 100 % (1.5 s); V 2000 mm/s, 0 \u2192 5000 mm",
        [](double t) { return t < 1.5 ? 0.2 : 1.0; }, w);
    expect(f, w[0].last > 400.0 - 1e-6 && w[0].last < 400.0 + 1e-6, "plateau at 400 mm/s");
    expect(f, w[1].last > 2000.0 - 1e-6, "2000 mm/s at 100 %");
    figures.push_back(f);
  }
  {
    // Start at 0 %: the axis waits at standstill, and moves once the override rises at 0.5 s.
    std::vector<Window> w = {{0.0, 0.5}};
    Figure f = run(
        out, "override_0_100",
        "Start at override 0 %, 100 % from 0.5 s; V 2000 mm/s, 0 \u2192 5000 mm",
        [](double t) { return t < 0.5 ? 0.0 : 1.0; }, w);
    expect(f, w[0].min == 0.0 && w[0].max == 0.0, "standstill while the override is 0 %");
    figures.push_back(f);
  }
  {
    // 0 % in motion at 1.0 s: the axis comes to rest on its path; it resumes at 2.0 s.
    std::vector<Window> w = {{1.7, 2.0}};
    Figure f = run(
        out, "override_100_0_100",
        "Override 100 % \u2192 0 % (1.0 s) \u2192 100 % (2.0 s); V 2000 mm/s, "
        "0 \u2192 5000 mm",
        [](double t) { return t < 1.0   ? 1.0
                              : t < 2.0 ? 0.0
                                        : 1.0; }, w);
    expect(f, w[0].min == 0.0 && w[0].max == 0.0, "at rest while the override is 0 %");
    figures.push_back(f);
  }
}

}  // namespace gallery
