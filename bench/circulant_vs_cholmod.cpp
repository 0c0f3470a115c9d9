// The block-circulant FFT solver (linalg/block_circulant_solver) against CHOLMOD (linalg/sparse_cholesky)
// on K_eff = M_ff / (beta dt^2) + (1 - a) K_ff of the paper's layer: factorization time, time per solve,
// time per column of Z = K_eff^{-1} C^T (the Delassus build), memory, and the largest relative difference
// of the solutions. A timed program (not a test); measure on one core:
//     OPENBLAS_NUM_THREADS=1 taskset -c 0 slidewave_bench_circulant
//     slidewave_bench_circulant --n 32 64 --lambda 2 --min-time 0.5
#include <Eigen/CholmodSupport>
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

#include "linalg/block_circulant_solver.hpp"
#include "linalg/sparse_cholesky.hpp"
#include "mesh_options.hpp"
#include "model/layer_model.hpp"
#include "time/hht_stepper.hpp"

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point start) { return std::chrono::duration<double>(Clock::now() - start).count(); }

/// Best of 5 batches of the mean time of one call (each batch about min_time / 5 s): the least disturbed
/// estimate on a shared machine.
template <class F>
double seconds_per_call(F&& call, double min_time) {
  int calls = 1;
  for (;;) {  // calibrate the batch length
    const auto start = Clock::now();
    for (int k = 0; k < calls; ++k) call();
    if (seconds_since(start) > min_time / 50 || calls > (1 << 24)) break;
    calls *= 2;
  }
  calls = std::max(1, calls * 10);
  std::vector<double> batches;
  for (int b = 0; b < 5; ++b) {
    const auto start = Clock::now();
    for (int k = 0; k < calls; ++k) call();
    batches.push_back(seconds_since(start) / calls);
  }
  return *std::min_element(batches.begin(), batches.end());
}

double relative_difference(const Eigen::MatrixXd& X, const Eigen::MatrixXd& X_ref) {
  return (X - X_ref).cwiseAbs().maxCoeff() / X_ref.cwiseAbs().maxCoeff();
}

/// Bytes CHOLMOD holds after a supernodal LL^T factorization (the factor and CHOLMOD's workspace), and its
/// peak during the factorization, from the CHOLMOD common of a factorization with SparseCholesky's settings.
std::pair<double, double> cholmod_memory_bytes(const Eigen::SparseMatrix<double>& A) {
  Eigen::CholmodDecomposition<Eigen::SparseMatrix<double>, Eigen::Lower> llt;
  llt.setMode(Eigen::CholmodSupernodalLLt);
  llt.compute(A);
  return {static_cast<double>(llt.cholmod().memory_inuse), static_cast<double>(llt.cholmod().memory_usage)};
}

}  // namespace

int main(int argc, char** argv) {
  // 1. Parse options.
  std::vector<int> resolutions;
  std::vector<double> lambdas;
  double min_time = 1.0;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if (slidewave::bench::mesh_option(a, argc, argv, i, resolutions, lambdas)) continue;
    if (a == "--min-time" && i + 1 < argc) {
      min_time = std::atof(argv[++i]);
    } else {
      std::fprintf(stderr, "usage: %s [--n N...] [--lambda L...] [--min-time SECONDS]\n", argv[0]);
      return 2;
    }
  }
  if (resolutions.empty()) resolutions = {32, 64, 128};
  if (lambdas.empty()) lambdas = {2, 6};

  std::printf(
      "# K_eff of the paper's layer (reduced integration, consistent mass, alpha = 0.1), one core;\n"
      "# times: best of 5 batches. solve: one right-hand side. Zcol: per column of K_eff^-1 C^T, solved\n"
      "# min(2 n_x, 64) unit columns at once. MB: factor + workspace (CHOLMOD: in use after the\n"
      "# factorization, and its peak). ratio: CHOLMOD solve / FFT solve.\n"
      "# max_rel: max|x - x_chol| / max|x_chol| over 3 random right-hand sides and the Z columns\n");
  std::printf("%8s %5s %5s %7s | %9s %9s %9s %8s %8s | %9s %9s %9s %7s | %6s %8s\n", "lambda/H", "H/h", "n_x", "n_dofs",
              "chol_fac", "chol_slv", "chol_Z", "chol_MB", "peak_MB", "fft_fac", "fft_slv", "fft_Z", "fft_MB", "ratio",
              "max_rel");
  std::printf("%8s %5s %5s %7s | %9s %9s %9s %8s %8s | %9s %9s %9s %7s | %6s %8s\n", "", "", "", "", "s", "ms",
              "ms/col", "", "", "s", "ms", "ms/col", "", "", "");
  for (double lambda_over_H : lambdas)
    for (int n : resolutions) {
      // 2. The matrix, as model/simulation.cpp builds it.
      slidewave::RunConfig config;
      config.mesh.elements_per_H = n;
      config.geometry.lambda_over_H = lambda_over_H;
      const slidewave::LayerModel model(config);
      const slidewave::HHTCoefficients hht(config.time.hht_alpha, model.d.dt);
      const Eigen::SparseMatrix<double> K_eff = slidewave::effective_matrix(hht, model.M_ff(), model.K_ff());
      const int n_x = model.mesh.n_x, n_y = model.mesh.n_y, n_free = model.n_free;

      // 3. Factorizations.
      auto start = Clock::now();
      const slidewave::SparseCholesky cholmod(K_eff);
      const double cholmod_factor_s = seconds_since(start);
      start = Clock::now();
      const slidewave::BlockCirculantSolver fft(K_eff, n_x, n_y);
      const double fft_factor_s = seconds_since(start);
      const auto [cholmod_bytes, cholmod_peak] = cholmod_memory_bytes(K_eff);

      // 4. One right-hand side: the project's CHOLMOD path against the allocation-free FFT path.
      std::mt19937_64 generator(1);
      std::uniform_real_distribution<double> uniform(-1.0, 1.0);
      Eigen::MatrixXd B(n_free, 3);
      for (Eigen::Index k = 0; k < B.size(); ++k) B.data()[k] = uniform(generator);
      Eigen::VectorXd b = B.col(0), x(n_free);
      const double cholmod_solve_s = seconds_per_call([&] { x = cholmod.solve(b); }, min_time);
      const double fft_solve_s = seconds_per_call([&] { fft.solve_into(b, x); }, min_time);

      // 5. Columns of Z = K_eff^{-1} C^T (contact DOFs are the first 2 n_x free DOFs); at most 64 of
      //    them, so that the largest case stays within memory (2 n_x columns of Z are 2.4 GB at H/128,
      //    lambda = 6H). The time per column does not depend on which columns.
      const int n_contact_dofs = std::min(2 * n_x, 64);
      Eigen::MatrixXd Ct = Eigen::MatrixXd::Zero(n_free, n_contact_dofs);
      for (int c = 0; c < n_contact_dofs; ++c) Ct(c, c) = 1;
      Eigen::MatrixXd Z_cholmod, Z_fft;
      const double cholmod_Z_s = seconds_per_call([&] { Z_cholmod = cholmod.solve(Ct); }, min_time);
      const double fft_Z_s = seconds_per_call([&] { Z_fft = fft.solve(Ct); }, min_time);

      // 6. Agreement.
      const double difference =
          std::max(relative_difference(fft.solve(B), cholmod.solve(B)), relative_difference(Z_fft, Z_cholmod));

      std::printf("%8g %5d %5d %7d | %9.4f %9.4f %9.4f %8.1f %8.1f | %9.4f %9.4f %9.4f %7.1f | %6.1f %8.1e\n",
                  lambda_over_H, n, n_x, n_free, cholmod_factor_s, 1e3 * cholmod_solve_s,
                  1e3 * cholmod_Z_s / n_contact_dofs, cholmod_bytes / 1e6, cholmod_peak / 1e6, fft_factor_s,
                  1e3 * fft_solve_s, 1e3 * fft_Z_s / n_contact_dofs, fft.memory_bytes() / 1e6,
                  cholmod_solve_s / fft_solve_s, difference);
      std::fflush(stdout);
    }
  return 0;
}
