#pragma once
// Everything the time loop of model/simulation.cpp carries from one step to the next: with it (and the
// model), the loop continues bit for bit. A checkpoint saves this struct.
#include <cstdint>
#include <string>
#include <vector>

#include "contact/coulomb_local.hpp"
#include "contact/friction_law.hpp"
#include "model/energy_ledger.hpp"
#include "time/hht_stepper.hpp"

namespace slidewave {

/// What the recorder carries between steps.
struct RecorderState {
  Eigen::VectorXd u_contact_start;  ///< contact DOFs at t = 0, relative with a substrate (slip is measured from them)
  std::size_t next_snapshot = 0;    ///< index of the next snapshot time (sorted)
  double t_first_opening = -1;      ///< time the interface first opened (-1: not yet)
};

struct LoopState {
  std::int64_t step = 0;              ///< steps done: the state is at t = step dt
  double t_end = 0;                   ///< end of the run: time.t_end, or earlier after stop_after_opening
  std::string end_reason = "t_end";   ///< why the run ends at t_end: t_end | stop_after_opening
  HHTState dynamics;                  ///< u, v, acc, K u, M_ff u, M_ff v, M_ff a, contact forces r
  std::vector<ContactState> contact;  ///< per contact node: open, stick, slip
  FrictionState friction;             ///< the friction law's memory (empty for Coulomb)
  EnergySums energy;                  ///< the energy ledger's running sums and F_top
  RecorderState recording;
  HHTState substrate;           ///< the substrate's dynamics (its mirrored frame); empty on a rigid flat
  EnergySums substrate_energy;  ///< the substrate's ledger (its contact work booked with S r)
};

}  // namespace slidewave
