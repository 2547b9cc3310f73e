// A user's first PLC program against ncsdk: enable one axis and position it to 100 mm.
// Exit code 0 when the move is Done at 100 mm; the install checks run it.
#include <cmath>
#include <cstdio>

#include <fb/fb.hpp>
#include <nc_core/cycle_driver.hpp>
#include <nc_core/kernel.hpp>

int main() {
  nc::Kernel kernel;
  nc::AxisConfig config;
  config.name = "Axis1";
  plc::AXIS_REF& axis = kernel.add_axis(config);

  fb::MC_Power power;
  fb::MC_MoveAbsolute move;
  nc::CycleDriver driver(kernel);
  driver.add_task("PlcTask", 0.002, [&] {
    power.Enable = true;
    power.Enable_Positive = true;
    power.Enable_Negative = true;
    power(axis);
    move.Execute = power.Status;
    move.Position = 100.0;
    move.Velocity = 500.0;
    move(axis);
  });

  const bool done = driver.run_until([&] { return move.Done || move.Error; }, 5.0);
  std::printf("consumer: Done=%d Error=%d ErrorID=0x%X ActPos=%.4f mm at t=%.3f s\n",
              move.Done ? 1 : 0, move.Error ? 1 : 0, static_cast<unsigned>(move.ErrorID),
              axis.NcToPlc.ActPos, driver.time());
  return done && move.Done && std::fabs(axis.NcToPlc.SetPos - 100.0) < 1e-9 ? 0 : 1;
}
