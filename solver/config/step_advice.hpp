#pragma once
// Advice on the time step of a run, printed by `slidewave check` and `slidewave run`, never an error: with
// unregularized Coulomb friction, long runs whose Courant number c_s dt / h is small create energy, a
// threshold in c_s dt / h, not in dt or h alone (5000 s runs, hht_alpha = 0.1, H/16 to H/64, nu 0 to 0.45,
// f 0.8 to 2: created at c_s dt / h <= 0.384 wherever the interface slid long enough, nowhere at >= 0.48;
// docs/physics-notes.md, section 8). The analysis categorizes such runs `non_physical`; the advice says so
// before the run is paid for. At the default dt c_s = 0.5 m it concerns meshes coarser than H/32.
#include <optional>
#include <string>

#include "config/run_config.hpp"

namespace slidewave {

/// Below this Courant number c_s dt / h a run with unregularized Coulomb friction gets the advice.
constexpr double kSmallCourantNumber = 0.5;

/// The advice for this configuration (one line, no newline), or none.
std::optional<std::string> small_step_advice(const RunConfig& config);

}  // namespace slidewave
