#pragma once
#include <cstdint>
// Wall-time split of a run (seconds), filled by simulate() when asked; used by bench/, never by tests.
namespace slidewave {

struct StepProfile {
  double setup = 0;        ///< preload stages, K_eff factorization, Delassus operator
  double stick_phase = 0;  ///< the steps taken in wavenumbers while every node sticks (model/stick_phase/)
  double predictor = 0;    ///< right-hand side of the free solve (~0: done by the previous correction)
  double free_solve = 0;   ///< K_eff u_free = rhs
  double contact = 0;      ///< Gauss–Seidel on W
  double correction = 0;   ///< u(n+1) from the contact forces, Newmark update, K u(n+1), mass products, next predictor
  double diagnostics = 0;  ///< energy ledger, friction memory, output rows
  std::int64_t steps = 0;
  std::int64_t stick_phase_steps = 0;
  long long contact_sweeps = 0;
};

}  // namespace slidewave
