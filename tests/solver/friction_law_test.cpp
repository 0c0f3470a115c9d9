// Friction laws (contact/friction_law.hpp): the registry maps friction.regularization to the law; the
// Coulomb law bounds friction by f r_y at every node and has no state; Prakash–Clifton starts its
// regularized normal force at the preload reaction, bounds friction by f sigma (released to f r_y at
// grazing), and relaxes sigma towards R_n with the implicit step theta = (|du_x| + v* dt) / L, checked on
// hand-computed values.
#include <gtest/gtest.h>

#include "contact/coulomb_friction.hpp"
#include "contact/prakash_clifton.hpp"

namespace slidewave {
namespace {

TEST(FrictionLaw, RegistryMakesTheConfiguredLaw) {
  FrictionConfig config;
  config.regularization = Regularization::none;
  EXPECT_NE(dynamic_cast<CoulombFriction*>(make_friction_law(config).get()), nullptr);
  config.regularization = Regularization::prakash_clifton;
  EXPECT_NE(dynamic_cast<PrakashClifton*>(make_friction_law(config).get()), nullptr);
}

TEST(FrictionLaw, CoulombBoundsFTimesPressureAndHasNoState) {
  const CoulombFriction law(1.5);
  const Eigen::VectorXd r = (Eigen::VectorXd(4) << -0.5, 2.0, 0.1, 3.0).finished();
  FrictionState state = law.initial_state(r);
  EXPECT_TRUE(state.per_node.empty());
  const auto bounds = law.bounds(state);
  EXPECT_EQ(bounds->f(), 1.5);
  EXPECT_FALSE(bounds->given_bound(0).has_value());
  EXPECT_EQ(bounds->bound(1, 2.0), 3.0);
  law.update(Eigen::VectorXd::Ones(4), r, 0.1, state);
  EXPECT_TRUE(state.per_node.empty());
}

TEST(FrictionLaw, PrakashCliftonStartsAtThePreloadAndRelaxesTowardsThePressure) {
  const double f = 1.5, L = 0.5, v_star = 0.3, dt = 0.2;
  const PrakashClifton law(f, L, v_star);
  const Eigen::VectorXd r0 = (Eigen::VectorXd(4) << -0.5, 2.0, 0.1, 3.0).finished();
  FrictionState state = law.initial_state(r0);
  EXPECT_EQ(state.per_node, (std::vector<double>{2.0, 3.0}));
  const auto bounds = law.bounds(state);
  EXPECT_EQ(bounds->given_bound(0).value_or(-1), f * 2.0);
  EXPECT_EQ(bounds->bound(1, 100.0), f * 3.0);

  // Node 0 slips by 0.2 (theta = (0.2 + 0.06) / 0.5 = 0.52), node 1 sticks (theta = 0.06 / 0.5 = 0.12).
  const Eigen::VectorXd du = (Eigen::VectorXd(4) << -0.2, 0.0, 0.0, 0.01).finished();
  const Eigen::VectorXd r1 = (Eigen::VectorXd(4) << 0.0, 4.0, 0.0, 0.0).finished();
  law.update(du, r1, dt, state);
  EXPECT_NEAR(state.per_node[0], (2.0 + 0.52 * 4.0) / 1.52, 1e-15);
  EXPECT_NEAR(state.per_node[1], 3.0 / 1.12, 1e-15);
  // Without slip and with v* = 0 the memory does not move.
  const PrakashClifton frozen(f, L, 0.0);
  FrictionState kept = frozen.initial_state(r0);
  frozen.update(Eigen::VectorXd::Zero(4), r1, dt, kept);
  EXPECT_EQ(kept.per_node, (std::vector<double>{2.0, 3.0}));
}

// Grazing (contact/prakash_clifton.hpp): a node whose open/closed status changes more than
// kMaxStatusChanges times in a pass gets f r_y for the rest of the pass; a new pass starts afresh.
TEST(FrictionLaw, PrakashCliftonReleasesACyclingNodeToFTimesPressure) {
  PrakashCliftonBounds bounds(2.0, {0.5, 0.7});
  bounds.start_pass(2);
  for (int change = 0; change < kMaxStatusChanges; ++change) bounds.status_changed(0);
  EXPECT_EQ(bounds.given_bound(0).value_or(-1), 0.5);
  bounds.status_changed(0);
  EXPECT_FALSE(bounds.given_bound(0).has_value());
  EXPECT_EQ(bounds.bound(0, 0.1), 2.0 * 0.1);
  EXPECT_EQ(bounds.given_bound(1).value_or(-1), 0.7);
  EXPECT_EQ(bounds.n_released(), 1);
  bounds.status_changed(0);
  EXPECT_EQ(bounds.n_released(), 1);
  bounds.start_pass(2);
  EXPECT_EQ(bounds.given_bound(0).value_or(-1), 0.5);
  EXPECT_EQ(bounds.n_released(), 0);
}

}  // namespace
}  // namespace slidewave
