#pragma once
// The single-mode seed (config group `mode_seed`): a displacement of the layer at one wavenumber, so that a
// run excites the mode whose speed or growth rate interface-wave theory predicts (docs/substrate.md,
// "Checks against the theory").
#include <Eigen/Dense>

#include "model/layer_model.hpp"

namespace slidewave {

/// The seed's displacement of the layer's free DOFs and top DOFs (zero there), or zeros without a
/// `mode_seed` group: u_x = A cos(k x) e^{-k y}, u_y = -A sin(k x) e^{-k y} (A = amplitude_over_H H,
/// k = 2 pi mode / lambda, y above the interface), the contact nodes' u_y left at 0 (no gap, no
/// penetration). The field is the gradient of a harmonic potential, A e^{-k y} sin(k x) / k, localized
/// within about 1 / k of the interface like an interface wave.
Eigen::VectorXd mode_seed_displacement(const LayerModel& m);

}  // namespace slidewave
