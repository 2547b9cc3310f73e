// The README's PLC program, as a user outside ncsdk writes it: enable one axis and position it
// to 2000 mm with a state machine in a 10 ms PLC task. Exit code 0 when the move is Done with
// the set position exactly on 2000 mm; the install checks build and run it.
#include <cstdio>

#include <fb/fb.hpp>
#include <nc_core/nc_core.hpp>

int main() {
  nc::Kernel kernel;  // NC cycle 1 ms (KernelConfig)
  nc::AxisConfig config;
  config.name = "Axis1";  // A 5000 mm/s², J 50000 mm/s³ by default
  plc::AXIS_REF& axis = kernel.add_axis(config);
  fb::MC_Power power;
  fb::MC_MoveAbsolute move;
  enum class State { kInit, kMove, kDone } state = State::kInit;

  nc::CycleDriver driver(kernel);
  driver.add_task("PlcTask", 0.010, [&] {  // 10 ms PLC task, runs before the NC
    power.Enable = power.Enable_Positive = power.Enable_Negative = true;
    power(axis);
    switch (state) {
      case State::kInit:
        if (power.Status) state = State::kMove;
        break;
      case State::kMove:
        move.Execute = true;
        move.Position = 2000.0;  // mm
        move.Velocity = 2000.0;  // mm/s
        if (move.Done) {
          move.Execute = false;
          state = State::kDone;
        }
        break;
      case State::kDone:
        break;
    }
    move(axis);
  });
  driver.run_until([&] { return state == State::kDone; }, 10.0);  // simulated seconds

  std::printf("consumer: %s, SetPos %.6f mm, ActPos %.4f mm at %.3f s (ErrorID 0x%X)\n",
              state == State::kDone ? "Done" : "not done", axis.NcToPlc.SetPos, axis.NcToPlc.ActPos,
              kernel.time(), static_cast<unsigned>(move.ErrorID));
  return state == State::kDone && axis.NcToPlc.SetPos == 2000.0 ? 0 : 1;
}
