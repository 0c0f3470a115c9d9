#include "model/substrate.hpp"

#include <cmath>

namespace slidewave {

RunConfig substrate_body_config(const RunConfig& layer) {
  const DerivedConstants d = layer.derived();
  const SubstrateConfig& s = layer.substrate;
  RunConfig body = layer;
  body.substrate = SubstrateConfig{};
  body.material = MaterialConfig{*s.E, *s.nu, *s.rho};
  const int n_y = substrate_rows(layer);
  body.mesh.elements_per_H = n_y;
  body.geometry.H = n_y * d.h;  // the layer's h exactly (H_s / n_y may differ from it by round-off)
  body.geometry.lambda_over_H = static_cast<double>(d.n_x) / n_y;
  body.time.dt = d.dt;  // the layer's step (its ledger and stepper use the model's dt)
  body.output.snapshot_times.clear();
  body.mode_seed = ModeSeedConfig{};  // the seed moves the layer only
  return body;
}

void mirror_x_components(Eigen::VectorXd& v) {
  for (Eigen::Index k = 0; k < v.size(); k += 2) v(k) = -v(k);
}

Eigen::MatrixXd pair_delassus(const Eigen::MatrixXd& W_layer, const Eigen::MatrixXd& W_substrate) {
  Eigen::MatrixXd W = W_layer;
  for (Eigen::Index j = 0; j < W.cols(); ++j)
    for (Eigen::Index i = 0; i < W.rows(); ++i) {
      const bool flip = (i % 2 == 0) != (j % 2 == 0);  // (S W_S S)(i, j) = s_i s_j W_S(i, j)
      W(i, j) += flip ? -W_substrate(i, j) : W_substrate(i, j);
    }
  return W;
}

Eigen::VectorXd relative_contact_displacement(const Eigen::VectorXd& u_layer, const Eigen::VectorXd& u_substrate,
                                              int n_contact_dofs) {
  Eigen::VectorXd u(n_contact_dofs);
  for (int k = 0; k < n_contact_dofs; k += 2) {
    u(k) = u_layer(k) - u_substrate(k);
    u(k + 1) = u_layer(k + 1) + u_substrate(k + 1);
  }
  return u;
}

}  // namespace slidewave
