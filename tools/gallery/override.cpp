// Seed 000 §2.2, "Override": the override changes the velocity level at once, as fast as A+, A-
// and J allow, with no undershoot; a start at 0 % waits; 0 % in motion rests on the path. Each
// figure: MC_MoveAbsolute 0 → 5000 mm at V 2000 mm/s, MC_SetOverride changing VelFactor at
// the times the title names.
#include <algorithm>
#include <functional>
#include <string>

#include "fb/mc_move_absolute.hpp"
#include "fb/mc_power.hpp"
#include "fb/mc_set_override.hpp"
#include "nc_core/scope.hpp"
#include "nc_core/svg_plot.hpp"
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

// The four override types of seed 000 §2.2 side by side: four axes, one per
// AxisConfig::override_type, each moving 0 → 800 mm at V 2000 mm/s (not reachable: the table
// at 100 % tops out below V, Dynamics 3.3), starting at 30 % and raised to 100 % at 1.0 s, when
// the remaining distance is too short for the new level. Types 1 and 3 scale the reduced level
// of the start, 2 and 4 the user's V; types 1 and 2 keep the old table when the new level is not
// reachable, 3 and 4 take the best level that is.
Figure override_types(const std::filesystem::path& out) {
  constexpr double kCycle = 0.001;
  constexpr double kEnd = 800.0;
  constexpr double kSeconds = 4.0;
  nc::Kernel kernel(nc::KernelConfig{kCycle});
  struct Lane {
    plc::AXIS_REF* axis = nullptr;
    std::string name;
    fb::MC_Power power;
    fb::MC_MoveAbsolute move;
    fb::MC_SetOverride set;
  };
  std::vector<Lane> lanes(4);
  nc::Scope scope(static_cast<std::size_t>(kSeconds / kCycle) + 4);
  for (int type = 1; type <= 4; ++type) {
    Lane& lane = lanes[static_cast<std::size_t>(type - 1)];
    nc::AxisConfig config = seed_axis();
    lane.name = "Type" + std::to_string(type);
    config.name = lane.name;
    config.override_type = type;
    lane.axis = &kernel.add_axis(config);
    lane.move.Position = kEnd;
    lane.move.Velocity = 2000.0;
    scope.add_signal(*lane.axis, lane.name, nc::Signal::kSetPos);
    scope.add_signal(*lane.axis, lane.name, nc::Signal::kSetVelo);
  }
  scope.add_signal(*lanes[0].axis, lanes[0].name, nc::Signal::kOverride);
  nc::CycleDriver driver(kernel);
  Figure f;
  f.name = "override_types";
  f.title = "Override types 1\u20134: 30 % \u2192 100 % at 1.0 s, V 2000 mm/s, 0 \u2192 800 mm";
  f.file = out / (f.name + ".svg");
  driver.add_task("Scope", kCycle, [&] { scope.record(kernel.time()); });
  driver.add_task("PlcTask", kCycle, [&] {
    for (Lane& lane : lanes) {
      lane.power.Enable = lane.power.Enable_Positive = lane.power.Enable_Negative = true;
      lane.power(*lane.axis);
      lane.set.Enable = true;
      lane.set.VelFactor = kernel.time() < 1.0 ? 0.3 : 1.0;
      lane.set(*lane.axis);
      lane.move.Execute = lane.power.Status;
      lane.move(*lane.axis);
      if (lane.move.Error) expect(f, false, lane.name + " MC_MoveAbsolute Error");
    }
  });
  driver.run_until(
      [&] {
        return std::all_of(lanes.begin(), lanes.end(), [](const Lane& l) { return l.move.Done; });
      },
      kSeconds - 0.3);
  driver.run_for(0.2);
  scope.record(kernel.time());
  for (const Lane& lane : lanes) {
    expect(f, lane.move.Done && lane.axis->NcToPlc.SetPos == kEnd, lane.name + " ends at 800 mm");
    expect(f, lane.axis->NcToPlc.ErrorCode == 0, lane.name + " axis error");
  }
  const char* colours[] = {"#00008b", "#006400", "#8b0000", "#ff7f00"};
  std::vector<nc::PlotPanel> panels(2);
  panels[0] = {"panel-position", "Set position", "mm", {}};
  panels[1] = {"panel-velocity", "Set velocity", "mm/s", {}};
  for (std::size_t i = 0; i < lanes.size(); ++i) {
    const std::string label = "override type " + std::to_string(i + 1);
    panels[0].series.push_back(
        {label, colours[i], scope.values(scope.find(lanes[i].name, nc::Signal::kSetPos)), 2.0});
    panels[1].series.push_back(
        {label, colours[i], scope.values(scope.find(lanes[i].name, nc::Signal::kSetVelo)), 2.0});
  }
  std::vector<double> percent;
  for (const double o : scope.values(scope.find(lanes[0].name, nc::Signal::kOverride))) {
    percent.push_back(o / 10'000.0);
  }
  panels.push_back(
      {"panel-override", "Override", "%", {{"PlcToNc.Override", "#6a3d9a", percent, 2.0}}});
  nc::write_svg(f.file, nc::svg_plot(scope.time(), panels, {f.title, 1000, 150}));
  return f;
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
  figures.push_back(override_types(out));
}

}  // namespace gallery
