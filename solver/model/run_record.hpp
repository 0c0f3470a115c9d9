#pragma once
// Everything a run produces, in memory, in the layout of run.h5 (docs/contracts.md, section 2).
// Rows are appended as the run goes (by model/recorder.hpp only); the file is written once at the end
// (atomically).
#include <cstdint>
#include <string>
#include <vector>

namespace slidewave {

/// Row-major (n_rows x n_cols) series that grows by rows.
template <typename T>
struct Series2D {
  int n_cols = 0;
  std::vector<T> data;
  int n_rows() const { return n_cols ? static_cast<int>(data.size() / n_cols) : 0; }
};

struct InterfaceSeries {
  std::vector<double> x, t;
  Series2D<double> slip_velocity, slip, opening, normal_traction, tangential_traction;
  Series2D<std::int8_t> state;
};

struct GlobalSeries {
  std::vector<double> t, T, N, T_over_N, energy_kinetic, energy_elastic, work_external, dissipation_friction,
      work_contact_normal, energy_balance_residual, contact_residual;
  std::vector<int> contact_iterations;
  /// Only with output.energy_decomposition = hht (model/energy_ledger.hpp): the HHT algorithmic
  /// dissipation, total and its three terms; empty otherwise.
  std::vector<double> dissipation_hht, dissipation_hht_gamma, dissipation_hht_beta, dissipation_hht_shift;
};

struct Snapshot {
  double t;
  std::vector<double> displacement, velocity;  ///< (n_nodes x 2), full mesh (x = lambda repeated)
};

struct SnapshotMesh {
  std::vector<double> coordinates;         ///< (n_nodes x 2)
  std::vector<std::int64_t> connectivity;  ///< (n_elements x 4)
};

struct RunRecord {
  InterfaceSeries interface;
  GlobalSeries global;
  SnapshotMesh snapshot_mesh;
  std::vector<Snapshot> snapshots;
  /// With a substrate (docs/substrate.md): its mesh (physical coordinates, y <= 0) and its fields at the
  /// snapshot times of `snapshots` (one each, same order); empty on a rigid flat.
  SnapshotMesh substrate_snapshot_mesh;
  std::vector<Snapshot> substrate_snapshots;
  bool complete = false;
  std::string end_reason;  ///< t_end | stop_after_opening | contact_not_converged | interrupted
  std::int64_t n_steps_done = 0;
  double t_first_opening = -1;   ///< stage-3 time the interface first opened (-1: never)
  double u_x_preshear = 0;       ///< top shear displacement at the end of stage 2 (m)
  double opening_threshold = 0;  ///< opening (m) above which a node counts as open (model/recorder.hpp)
  int static_contact_iterations = 0;
};

}  // namespace slidewave
