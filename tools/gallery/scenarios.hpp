// The gallery's scenario groups: each plays seed 000's figures (or the scenarios of issue 4
// built on them) through the real blocks, kernel, cycle driver and scope, and appends one
// Figure per SVG written into `out`.
#pragma once

#include <filesystem>
#include <vector>

#include "rig.hpp"

namespace gallery {

using Figures = std::vector<Figure>;

// Seed 000 §2.1: Dynamics 1.1–1.3 (A+/A-), 2.1–2.3 (jerk), 3.1–3.3 (velocity reduction).
void dynamics(const std::filesystem::path& out, Figures& figures);
// Seed 000 §2.2: override 100 → 75 → 100 %, 20 → 100 %, a start at 0 %, 0 % in motion.
void override_changes(const std::filesystem::path& out, Figures& figures);
// Seed 000 §2.2: stop with emergency parameters (adopted, not adopted).
void stops(const std::filesystem::path& out, Figures& figures);
// Seed 000 §2.3: new end position during the stop phase, and with reversal.
void new_end_position(const std::filesystem::path& out, Figures& figures);
// Seed 000 §2.4: new velocity and new end position, cases 1–6.
void new_velocity_and_end_position(const std::filesystem::path& out, Figures& figures);
// Seed 000 §2.1: modulo starts (540 with factor 360, the four directions).
void modulo(const std::filesystem::path& out, Figures& figures);
// Continuous motion: MC_MoveVelocity, a velocity change, a reversal, MC_Halt.
void continuous_motion(const std::filesystem::path& out, Figures& figures);

}  // namespace gallery
