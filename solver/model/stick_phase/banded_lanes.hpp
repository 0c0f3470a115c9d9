#pragma once
// Real symmetric banded matrices of one mesh column, one per wavenumber ("lane" m), applied to complex
// vectors (the lanes' states), stored with the lane fastest so that every loop over rows runs a
// vectorizable inner loop over the active lanes (the layout of linalg/block_circulant_solver.hpp). A row r
// of a lane-vector X is X.re[r lanes + m], X.im[r lanes + m]. Used by the stick-phase stepper
// (docs/stick-phase.md; model/stick_phase/wavenumber_blocks.hpp says why the matrices are real).
#include <complex>
#include <cstddef>
#include <vector>

namespace slidewave {

/// rows x lanes complex values, split into real and imaginary parts, lane fastest.
struct LaneVectors {
  int rows = 0, lanes = 0;
  std::vector<double> re, im;
  LaneVectors() = default;
  LaneVectors(int n_rows, int n_lanes)
      : rows(n_rows), lanes(n_lanes), re(static_cast<std::size_t>(n_rows) * n_lanes, 0.0), im(re.size(), 0.0) {}
  std::size_t at(int r, int m) const { return static_cast<std::size_t>(r) * lanes + m; }
  std::complex<double> get(int r, int m) const { return {re[at(r, m)], im[at(r, m)]}; }
  void set(int r, int m, std::complex<double> z) {
    re[at(r, m)] = z.real();
    im[at(r, m)] = z.imag();
  }
  /// Keeps lanes [0, width) only (width <= lanes), in place.
  void narrow(int width);
};

/// A real symmetric banded matrix per lane, entries (r, r + k) for |k| <= p (zero outside [0, rows)),
/// applied to complex lane-vectors (its real and imaginary parts apart).
struct BandedLanes {
  int rows = 0, p = 0, lanes = 0;
  std::vector<double> a;  ///< entry (r, r + k) of lane m at ((r (2p+1) + k + p) lanes + m)
  BandedLanes() = default;
  BandedLanes(int n_rows, int half_bandwidth, int n_lanes);
  std::size_t at(int r, int k, int m) const { return (static_cast<std::size_t>(r) * (2 * p + 1) + k + p) * lanes + m; }
  double get(int r, int k, int m) const { return a[at(r, k, m)]; }

  /// y(rows [r0, r1)) = A x for lanes [0, m_end) (x and y distinct); with accumulate, y += scale A x.
  void multiply(const LaneVectors& x, LaneVectors& y, int r0, int r1, int m_end, bool accumulate = false,
                double scale = 1) const;
  /// Keeps lanes [0, width) only (width <= lanes), in place.
  void narrow(int width);
  /// A copy of lanes [0, width) of rows [0, n_rows) (all rows if n_rows < 0).
  BandedLanes first_lanes(int width, int n_rows = -1) const;
};

/// L D L^T of the trailing block of a BandedLanes (rows and columns [first, rows)), lane by lane, and
/// its solves (row-oriented band LDL^T of Golub & Van Loan, sec. 4.3, as in
/// linalg/block_circulant_solver.cpp). Throws std::runtime_error if a lane's block is not positive definite.
class BandedLaneFactor {
 public:
  BandedLaneFactor() = default;
  BandedLaneFactor(const BandedLanes& A, int first);
  /// Solves in place on rows [first, rows) of x, lanes [0, m_end) (x as narrow as the factor).
  void solve(LaneVectors& x, int m_end) const;
  /// Keeps lanes [0, width) only (width <= its lanes), in place.
  void narrow(int width);

 private:
  int first_ = 0, n_ = 0, p_ = 0, lanes_ = 0;
  std::vector<double> L_;      ///< entry (q, q - k), k = 1..p, of lane m at ((q p + k - 1) lanes + m)
  std::vector<double> inv_D_;  ///< 1 / D(q) at q lanes + m
};

/// Per lane, whether the trailing block (rows and columns [first, rows)) of A is positive definite: its band
/// L D L^T has positive pivots only. For A = K - sigma M (M positive definite) that says, by Sylvester's law of
/// inertia, that every eigenvalue of K x = lambda M x on the block is above sigma.
std::vector<bool> positive_definite_lanes(const BandedLanes& A, int first);

}  // namespace slidewave
