// Refusals of MC_MoveSuperImposed and MC_AbortSuperposition (seed 000 §2.5, SPEC B7): every bad
// start parameter and every forbidden state has its code, and a refused compensation disturbs
// nothing — the NC→PLC image stays bit-identical to a twin kernel that never saw the command.
#include <catch2/catch.hpp>

#include <limits>

#include "kernel_harness.hpp"

using plc::CommandState;
using plc::CommandType;
using plc::ErrorCode;

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

plc::Command good() {
  return kt::move_superimposed(250.0, 300.0, 500.0, 1000.0, 2000.0, 5000.0);
}

// Twin kernels running the same basic motion; `bad` goes to one of them only. Checks the code
// and that both images stay identical for 300 cycles.
void check_refused(const plc::Command& bad, ErrorCode expected,
                   void (*prepare)(kt::Harness&) = nullptr) {
  kt::Harness h;
  kt::Harness twin;
  for (kt::Harness* k : {&h, &twin}) {
    if (prepare != nullptr) {
      prepare(*k);
    } else {
      k->post(kt::move_absolute(10000.0, 2000.0));
      k->cycles(600);
    }
  }
  const uint16_t n = h.post(bad);
  h.cycles(1);
  twin.cycles(1);
  CHECK(h.answer(n).state == CommandState::kError);
  CHECK(h.answer(n).error_code == kt::id(expected));
  for (int i = 0; i < 300; ++i) {
    REQUIRE(kt::same_image(h.x->NcToPlc, twin.x->NcToPlc));
    h.cycles(1);
    twin.cycles(1);
  }
}

}  // namespace

TEST_CASE("bad compensation start parameters are refused with their codes",
          "[compensation][refusals]") {
  struct Case {
    const char* what;
    plc::Command command;
    ErrorCode code;
  };
  auto with = [](auto change) {
    plc::Command c = good();
    change(c);
    return c;
  };
  const Case cases[] = {
      {"D 0", with([](plc::Command& c) { c.position = 0.0; }),
       ErrorCode::kCompensationParametersInvalid},
      {"D NaN", with([](plc::Command& c) { c.position = kNaN; }), ErrorCode::kPositionNotFinite},
      {"D -inf", with([](plc::Command& c) { c.position = -kInf; }), ErrorCode::kPositionNotFinite},
      {"L 0", with([](plc::Command& c) { c.length = 0.0; }), ErrorCode::kCompensationLengthInvalid},
      {"L < 0", with([](plc::Command& c) { c.length = -5000.0; }),
       ErrorCode::kCompensationLengthInvalid},
      {"L NaN", with([](plc::Command& c) { c.length = kNaN; }), ErrorCode::kParameterNotFinite},
      {"VK 0", with([](plc::Command& c) { c.velocity = 0.0; }),
       ErrorCode::kCompensationVelocityInvalid},
      {"VK < 0", with([](plc::Command& c) { c.velocity = -300.0; }),
       ErrorCode::kCompensationVelocityInvalid},
      {"VP 0", with([](plc::Command& c) { c.process_velocity = 0.0; }),
       ErrorCode::kCompensationVelocityInvalid},
      {"VP inf", with([](plc::Command& c) { c.process_velocity = kInf; }),
       ErrorCode::kParameterNotFinite},
      {"AK+ 0", with([](plc::Command& c) { c.acceleration = 0.0; }),
       ErrorCode::kCompensationAccelerationInvalid},
      {"AK- < 0", with([](plc::Command& c) { c.deceleration = -1000.0; }),
       ErrorCode::kCompensationAccelerationInvalid},
      {"AK- NaN", with([](plc::Command& c) { c.deceleration = kNaN; }),
       ErrorCode::kParameterNotFinite},
  };
  for (const Case& c : cases) {
    INFO(c.what);
    check_refused(c.command, c.code);
  }
}

TEST_CASE("compensation parameters outside [1e-9, 1e12] are refused with their codes",
          "[compensation][refusals][range]") {
  // Fuzz finding K3: D = VK = AK+ = AK- = VP = L = 1.8e-322 all passed "> 0" and TargetPos
  // became inf / NaN.
  const double denormal = 1.8e-322;
  check_refused(kt::move_superimposed(denormal, denormal, denormal, denormal, denormal, denormal),
                ErrorCode::kCompensationParametersInvalid);
  using C = plc::Command;
  const struct {
    double C::*field;
    double sign;
    ErrorCode code;
  } fields[] = {{&C::position, -1.0, ErrorCode::kCompensationParametersInvalid},
                {&C::length, 1.0, ErrorCode::kCompensationLengthInvalid},
                {&C::velocity, 1.0, ErrorCode::kCompensationVelocityInvalid},
                {&C::process_velocity, 1.0, ErrorCode::kCompensationVelocityInvalid},
                {&C::acceleration, 1.0, ErrorCode::kCompensationAccelerationInvalid},
                {&C::deceleration, 1.0, ErrorCode::kCompensationAccelerationInvalid}};
  for (double bad : {denormal, 0.99e-9, 1.01e12, 1e300}) {
    for (const auto& f : fields) {
      INFO("bad value " << f.sign * bad << " in field " << (&f - fields));
      plc::Command c = good();
      c.*f.field = f.sign * bad;
      check_refused(c, f.code);
    }
  }
}

TEST_CASE("an encoder axis cannot carry out a compensation (0x4040)", "[compensation][refusals]") {
  nc::AxisConfig config = kt::seed_axis();
  config.kind = nc::AxisKind::kEncoder;
  kt::Harness h(config);
  h.post(kt::move_absolute(10000.0, 2000.0));
  h.cycles(600);
  const uint16_t n = h.post(good());
  h.cycles(1);
  CHECK(h.answer(n).error_code == kt::id(ErrorCode::kAxisKindNotAllowed));
  CHECK_FALSE(kt::bit(*h.x, plc::kStateCompensating));
}

TEST_CASE("no compensation without a basic motion to superimpose (0x424E)",
          "[compensation][refusals]") {
  check_refused(good(), ErrorCode::kFunctionNotAllowed, [](kt::Harness& h) { h.cycles(10); });
  // A positioning whose set-value generation has ended (waiting for the target window).
  check_refused(good(), ErrorCode::kFunctionNotAllowed, [](kt::Harness& h) {
    h.post(kt::move_absolute(10.0, 1000.0));
    h.cycles_until([&] { return h.x->NcToPlc.SetPos == 10.0; });
  });
}

TEST_CASE(
    "no compensation start during the stop phase (0x4242) or under the MC_Stop lock "
    "(0x42EF)",
    "[compensation][refusals]") {
  check_refused(good(), ErrorCode::kStopAlreadyActive, [](kt::Harness& h) {
    h.post(kt::move_absolute(10000.0, 2000.0));
    h.cycles(600);
    h.post(kt::simple(CommandType::kHalt));
    h.cycles(10);
  });
  check_refused(good(), ErrorCode::kStopAlreadyActive, [](kt::Harness& h) {
    h.post(kt::move_absolute(10000.0, 2000.0));
    h.cycles(600);
    h.post(kt::simple(CommandType::kStop));
    h.cycles(10);
  });
  check_refused(good(), ErrorCode::kMotionCommandsLocked, [](kt::Harness& h) {
    h.post(kt::move_velocity(100.0, 1));
    h.cycles(600);
    const uint16_t stop = h.post(kt::simple(CommandType::kStop));
    h.cycles_until([&] { return h.state_of(stop) == CommandState::kDone; });
    h.post(kt::move_velocity(100.0, 1));  // refused: locked; the axis stands
    h.cycles(1);
  });
}

TEST_CASE("no compensation while one is active: no iteration (0x4245)",
          "[compensation][refusals]") {
  check_refused(good(), ErrorCode::kCompensationActive, [](kt::Harness& h) {
    h.post(kt::move_absolute(10000.0, 2000.0));
    h.cycles(600);
    h.post(good());
    h.cycles(100);
  });
}

TEST_CASE("no compensation on an axis in error (0x4F06)", "[compensation][refusals]") {
  check_refused(good(), ErrorCode::kAxisInErrorState, [](kt::Harness& h) {
    h.post(kt::move_absolute(10000.0, 2000.0));
    h.cycles(600);
    kt::set_enables(*h.x, true, false, true);  // feed enable plus removed while moving: 0x4358
    h.cycles(10);
  });
}

TEST_CASE("no compensation beside external setpoint generation (0x424E)",
          "[compensation][refusals]") {
  check_refused(good(), ErrorCode::kFunctionNotAllowed, [](kt::Harness& h) {
    h.post(kt::move_absolute(10000.0, 2000.0));
    h.cycles(600);
    h.post(kt::ext_enable(0.0, 2));
    h.cycles(10);
  });
}

TEST_CASE("a compensation that would end beyond an enabled software limit is refused (0x4222)",
          "[compensation][refusals]") {
  nc::AxisConfig config = kt::seed_axis();
  config.sw_limit_max_enabled = true;
  config.sw_limit_max = 10100.0;
  kt::Harness h(config);
  h.post(kt::move_absolute(10000.0, 2000.0));
  h.cycles(600);
  const uint16_t far = h.post(good());  // 10000 + 250 > 10100
  h.cycles(1);
  CHECK(h.answer(far).error_code == kt::id(ErrorCode::kTargetPositionNotAllowed));
  CHECK(h.x->NcToPlc.CompensationLength == 0.0);  // nothing of it was published
  plc::Command near = good();
  near.position = 80.0;
  const uint16_t ok = h.post(near);
  h.cycles(1);
  CHECK(h.state_of(ok) == CommandState::kActive);
}
