#pragma once
// The series of run.h5 (docs/contracts.md section 2) as the writers lay them out: dataset names,
// units and descriptions, and the name of snapshot k. One list for writing, resuming and reading back.
#include <cstdio>
#include <string>
#include <vector>

#include "model/run_record.hpp"

namespace slidewave::run_layout {

struct DatasetText {
  const char* unit;
  const char* description;
};

struct GlobalColumn {
  const char* name;
  std::vector<double> GlobalSeries::*values;
  DatasetText text;
};
inline const GlobalColumn kGlobalColumns[] = {
    {"t", &GlobalSeries::t, {"s", "time of every step, stage-3 clock"}},
    {"T", &GlobalSeries::T, {"N/m", "tangential force on the interface, -sum R_t, per unit depth"}},
    {"N", &GlobalSeries::N, {"N/m", "normal force on the interface, sum R_n, per unit depth"}},
    {"T_over_N", &GlobalSeries::T_over_N, {"1", "apparent friction T/N"}},
    {"energy_kinetic", &GlobalSeries::energy_kinetic, {"J/m", "kinetic energy 1/2 v.M v"}},
    {"energy_elastic", &GlobalSeries::energy_elastic, {"J/m", "elastic energy 1/2 u.K u (includes the preload)"}},
    {"work_external", &GlobalSeries::work_external, {"J/m", "work of the imposed top displacement since t = 0"}},
    {"dissipation_friction",
     &GlobalSeries::dissipation_friction,
     {"J/m", "frictional dissipation -sum 1/2 (R_t(n)+R_t(n+1)) du_x since t = 0"}},
    {"work_contact_normal",
     &GlobalSeries::work_contact_normal,
     {"J/m", "energy lost by the normal contact forces, -sum 1/2 (R_n(n)+R_n(n+1)) du_y"}},
    {"energy_balance_residual",
     &GlobalSeries::energy_balance_residual,
     {"J/m", "E_kin + E_el + D_fric + W_normal - E(0) - W_ext (HHT dissipation for alpha > 0)"}},
    {"contact_residual", &GlobalSeries::contact_residual, {"1", "last sweep's max reaction change / (p0 h)"}},
};
/// Written only with output.energy_decomposition = hht (docs/energy-balance.md).
inline const GlobalColumn kHhtColumns[] = {
    {"dissipation_hht",
     &GlobalSeries::dissipation_hht,
     {"J/m",
      "HHT algorithmic dissipation since t = 0, the sum of the three terms below (= -energy_balance_residual "
      "to round-off)"}},
    {"dissipation_hht_gamma",
     &GlobalSeries::dissipation_hht_gamma,
     {"J/m", "-sum dt (gamma - 1/2) <v>.M [a] (velocity update)"}},
    {"dissipation_hht_beta",
     &GlobalSeries::dissipation_hht_beta,
     {"J/m", "sum dt^2 (beta - gamma/2) [a].M <a> (displacement update)"}},
    {"dissipation_hht_shift",
     &GlobalSeries::dissipation_hht_shift,
     {"J/m", "-sum [u].<s>, s(n+1) = alpha K [u] - a' C^T [r] (alpha-shift of K u and of the contact forces)"}},
};
inline const DatasetText kIterationsText{"1", "Gauss-Seidel sweeps of the step"};

struct InterfaceColumn {
  const char* name;
  Series2D<double> InterfaceSeries::*values;
  DatasetText text;
};
inline const InterfaceColumn kInterfaceColumns[] = {
    {"slip_velocity", &InterfaceSeries::slip_velocity, {"m/s", "du_x/dt over the step ending at t (contact nodes)"}},
    {"slip", &InterfaceSeries::slip, {"m", "u_x of the contact nodes relative to t = 0"}},
    {"opening", &InterfaceSeries::opening, {"m", "u_y of the contact nodes (gap to the rigid flat)"}},
    {"normal_traction", &InterfaceSeries::normal_traction, {"Pa", "contact pressure, compression positive (R_n/h)"}},
    {"tangential_traction",
     &InterfaceSeries::tangential_traction,
     {"Pa", "frictional traction, positive when resisting sliding in +x (-R_t/h)"}},
};
inline const DatasetText kInterfaceTimeText{"s", "output times, stage-3 clock"};
inline const DatasetText kStateText{"1", "0 open, 1 stick, 2 slip"};
inline const DatasetText kInterfaceXText{"m", "position of the contact nodes (x = lambda is x = 0)"};

/// Group name of snapshot k: "0000", "0001", ...
inline std::string snapshot_id(std::size_t k) {
  char id[32];
  std::snprintf(id, sizeof id, "%04zu", k);
  return id;
}

}  // namespace slidewave::run_layout
