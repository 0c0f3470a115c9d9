#include "model/mode_seed.hpp"

#include <cmath>

namespace slidewave {

Eigen::VectorXd mode_seed_displacement(const LayerModel& m) {
  Eigen::VectorXd du = Eigen::VectorXd::Zero(m.n_free + m.n_top);
  const ModeSeedConfig& seed = m.config.mode_seed;
  if (!seed.present()) return du;
  const double amplitude = *seed.amplitude_over_H * m.d.H;
  const double k = 2.0 * M_PI * seed.mode / m.d.lambda;
  for (int j = 0; j < m.mesh.n_y; ++j)  // the free rows; the top row n_y is prescribed
    for (int i = 0; i < m.mesh.n_x; ++i) {
      const int node = m.mesh.node(i, j);
      const double x = m.mesh.x(node), decay = amplitude * std::exp(-k * m.mesh.y(node));
      du(2 * node) = decay * std::cos(k * x);
      if (j > 0) du(2 * node + 1) = -decay * std::sin(k * x);
    }
  return du;
}

}  // namespace slidewave
