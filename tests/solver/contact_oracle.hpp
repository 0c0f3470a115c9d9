#pragma once
// Independent oracles for the frictional contact problem  y = q + W r  (node k: y = (du_x, u_y),
// r = (r_x, r_y)), shared by coulomb_local_test and contact_solver_test:
//  - signorini_coulomb_violations: the conditions checked directly on (r, y);
//  - enumerate_solutions: brute force over the 4^n state combinations (open, stick, slip +, slip -),
//    one linear system each, keeping every solution that satisfies all conditions.
#include <Eigen/Dense>
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

namespace slidewave::testing {

/// Empty if (r, y = q + W r) satisfies, node by node and within tol (absolute, on r and y alike):
///   Signorini  u_y >= 0, r_y >= 0, r_y u_y = 0;
///   Coulomb    |r_x| <= f r_y, and du_x != 0  =>  r_x = -f r_y sign(du_x).
inline std::string signorini_coulomb_violations(const Eigen::MatrixXd& W, const Eigen::VectorXd& q, double f,
                                                const Eigen::VectorXd& r, double tol) {
  const Eigen::VectorXd y = q + W * r;
  std::ostringstream out;
  for (int k = 0; k < static_cast<int>(q.size() / 2); ++k) {
    const double rx = r(2 * k), ry = r(2 * k + 1), dux = y(2 * k), uy = y(2 * k + 1);
    if (ry < -tol) out << "node " << k << ": r_y = " << ry << " < 0\n";
    if (uy < -tol) out << "node " << k << ": penetration u_y = " << uy << "\n";
    if (std::fabs(ry) > tol && std::fabs(uy) > tol) out << "node " << k << ": r_y u_y != 0\n";
    if (std::fabs(rx) > f * ry + tol) out << "node " << k << ": |r_x| = " << std::fabs(rx) << " > f r_y\n";
    if (std::fabs(dux) > tol && std::fabs(rx + f * ry * (dux > 0 ? 1 : -1)) > tol)
      out << "node " << k << ": slips (du_x = " << dux << ") but r_x = " << rx << " != -f r_y sign\n";
  }
  return out.str();
}

enum class TrialState { open, stick, slip_forward, slip_backward };

/// Every r that solves the problem, found by enumerating the 4^n state combinations
/// (duplicates within tol removed). Singular combinations are skipped.
inline std::vector<Eigen::VectorXd> enumerate_solutions(const Eigen::MatrixXd& W, const Eigen::VectorXd& q, double f,
                                                        double tol) {
  const int n = static_cast<int>(q.size() / 2);
  int n_combinations = 1;
  for (int k = 0; k < n; ++k) n_combinations *= 4;
  std::vector<Eigen::VectorXd> solutions;
  for (int code = 0; code < n_combinations; ++code) {
    Eigen::MatrixXd A = Eigen::MatrixXd::Zero(2 * n, 2 * n);
    Eigen::VectorXd rhs = Eigen::VectorXd::Zero(2 * n);
    std::vector<TrialState> states(n);
    for (int k = 0, c = code; k < n; ++k, c /= 4) {
      states[k] = static_cast<TrialState>(c % 4);
      const int ix = 2 * k, iy = 2 * k + 1;
      switch (states[k]) {
        case TrialState::open:  // r_k = 0
          A(ix, ix) = 1;
          A(iy, iy) = 1;
          break;
        case TrialState::stick:  // y_k = 0
          A.row(ix) = W.row(ix);
          A.row(iy) = W.row(iy);
          rhs(ix) = -q(ix);
          rhs(iy) = -q(iy);
          break;
        case TrialState::slip_forward:
        case TrialState::slip_backward: {  // u_y = 0, r_x + s f r_y = 0
          const double s = states[k] == TrialState::slip_forward ? 1.0 : -1.0;
          A(ix, ix) = 1;
          A(ix, iy) = s * f;
          A.row(iy) = W.row(iy);
          rhs(iy) = -q(iy);
          break;
        }
      }
    }
    const Eigen::FullPivLU<Eigen::MatrixXd> lu(A);
    if (lu.rank() < 2 * n) continue;
    const Eigen::VectorXd r = lu.solve(rhs);
    const Eigen::VectorXd y = q + W * r;
    bool ok = true;
    for (int k = 0; k < n && ok; ++k) {
      const double rx = r(2 * k), ry = r(2 * k + 1), dux = y(2 * k), uy = y(2 * k + 1);
      switch (states[k]) {
        case TrialState::open:
          ok = uy >= -tol;
          break;
        case TrialState::stick:
          ok = ry >= -tol && std::fabs(rx) <= f * ry + tol;
          break;
        case TrialState::slip_forward:
          ok = ry >= -tol && dux >= -tol;
          break;
        case TrialState::slip_backward:
          ok = ry >= -tol && dux <= tol;
          break;
      }
    }
    if (!ok) continue;
    bool duplicate = false;
    for (const auto& s : solutions) duplicate = duplicate || (s - r).cwiseAbs().maxCoeff() <= 1e3 * tol;
    if (!duplicate) solutions.push_back(r);
  }
  return solutions;
}

}  // namespace slidewave::testing
