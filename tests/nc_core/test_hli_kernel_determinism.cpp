// Determinism and "a refused list disturbs nothing" on the real kernel: the same PLC program with
// HLI lists in force run twice gives the same NC image bit for bit at every tick; and a run where
// refused lists (70397, 70396, unknown ax_nr) are set while the axes move gives, bit for bit, the
// image of the run without them; so does one where external setpoints on a target are refused.
#include <catch2/catch.hpp>

#include <bit>
#include <cstdint>
#include <functional>
#include <vector>

#include "hli_kernel_rig.hpp"

using namespace hlik;

namespace {

std::vector<uint64_t> image(const Rig& rig) {
  std::vector<uint64_t> out;
  for (const plc::AXIS_REF* a : rig.axes) {
    const plc::NCTOPLC_AXIS_REF& o = a->NcToPlc;
    for (const double v : {o.SetPos, o.SetVelo, o.SetAcc, o.ActPos, o.ActVelo, o.PosDiff})
      out.push_back(std::bit_cast<uint64_t>(v));
    out.push_back(o.StateDWord);
    out.push_back(o.ErrorCode);
  }
  return out;
}

// Three axes moving back and forth; `plc` runs before each tick.
std::vector<std::vector<uint64_t>> run(const std::function<void(Rig&, int)>& plc) {
  Rig rig({axis(1, "X"), axis(2, "Y"), axis(8, "Y2")});
  std::vector<std::vector<uint64_t>> trace;
  for (int n = 0; n < 2500; ++n) {
    for (std::size_t i = 0; i < 3; ++i) {
      rig.move[i].Position = n < 1200 ? 300.0 + 50.0 * static_cast<double>(i) : -20.0;
      rig.move[i].Velocity = 1200.0;
      rig.move[i].Execute = n % 1200 > 5;
    }
    plc(rig, n);
    rig.tick();
    trace.push_back(image(rig));
  }
  return trace;
}

void set_list(Rig& rig, std::size_t axis_index, List list) {
  fb::HLI_AxisCoupling& c = rig.coupling[axis_index];
  c.desc = {};
  std::size_t k = 0;
  for (const h::HLI_AX_COUPLING_DESC& d : list)
    c.desc[k++] = d;
}

}  // namespace

TEST_CASE("The same program with HLI lists in force gives the same image bit for bit",
          "[hli][kernel][determinism]") {
  const auto plc = [](Rig& rig, int n) {
    if (n == 0) {
      set_list(rig, 2,
               {{1, h::HLI_AXIS_COUPLING_FRACT, -5, 9},
                {8, h::HLI_AXIS_COUPLING_DIRECT, 0, 0},
                {2, h::HLI_AXIS_COUPLING_MIRROR, 0, 0}});
    }
    rig.coupling[2].Execute = n < 3;
  };
  const auto a = run(plc);
  const auto b = run(plc);
  REQUIRE(a.size() == b.size());
  for (std::size_t t = 0; t < a.size(); ++t)
    REQUIRE(a[t] == b[t]);
  const auto plain = run([](Rig&, int) {});
  CHECK(a.back() != plain.back());  // the list did act
}

TEST_CASE("Refused lists set while the axes move change nothing, bit for bit",
          "[hli][kernel][determinism]") {
  const auto plain = run([](Rig&, int) {});
  const auto refused = run([](Rig& rig, int n) {
    if (n == 300) set_list(rig, 2, {{1, h::HLI_AXIS_COUPLING_FRACT, 1001, 1}});  // 70397
    if (n == 600) set_list(rig, 0, {{2, h::HLI_AXIS_COUPLING_FRACT, 1, 0}});     // 70396
    if (n == 900) set_list(rig, 1, {{99, h::HLI_AXIS_COUPLING_DIRECT, 0, 0}});   // unknown
    rig.coupling[2].Execute = n >= 300 && n < 310;
    rig.coupling[0].Execute = n >= 600 && n < 610;
    rig.coupling[1].Execute = n >= 900 && n < 910;
    if (n == 305) CHECK(rig.coupling[2].ErrorID == 70397);
    if (n == 605) CHECK(rig.coupling[0].ErrorID == 70396);
    if (n == 905) CHECK(rig.coupling[1].Error);
  });
  REQUIRE(plain.size() == refused.size());
  for (std::size_t t = 0; t < plain.size(); ++t)
    REQUIRE(plain[t] == refused[t]);
}

TEST_CASE("External setpoints refused on a coupled target change nothing, bit for bit",
          "[hli][kernel][determinism]") {
  const auto coupled = [](Rig& rig, int n) {
    if (n == 0) {
      set_list(rig, 2,
               {{1, h::HLI_AXIS_COUPLING_DIRECT, 0, 0}, {8, h::HLI_AXIS_COUPLING_DIRECT, 0, 0}});
    }
    rig.coupling[2].Execute = n < 3;
  };
  const auto plain = run(coupled);
  uint16_t absolute = 0;
  uint16_t relative = 0;
  const auto refused = run([&](Rig& rig, int n) {
    coupled(rig, n);
    if (n == 400) absolute = rig.axes[2]->Mailbox.post(kt::ext_enable(0.0, 1));
    if (n == 1500) relative = rig.axes[2]->Mailbox.post(kt::ext_enable(0.0, 2));
    if (n == 402) CHECK(rig.axes[2]->Mailbox.answer(absolute).error_code == 0x424E);
    if (n == 1502) CHECK(rig.axes[2]->Mailbox.answer(relative).error_code == 0x424E);
  });
  REQUIRE(plain.size() == refused.size());
  for (std::size_t t = 0; t < plain.size(); ++t)
    REQUIRE(plain[t] == refused[t]);
}
