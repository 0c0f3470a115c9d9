#include "model/stick_phase/banded_lanes.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "linalg/vector_clones.hpp"

namespace slidewave {

namespace {

/// Keeps the first `width` of the `lanes` values of each of n_rows rows, packed at the new row length, in place
/// (the storage is not reallocated: no new pages). Retired lanes leave the stepper's arrays this way, so that
/// the active ones stay contiguous in memory (model/stick_phase/wavenumber_stepper.hpp).
void keep_first_lanes(std::vector<double>& a, std::size_t n_rows, int lanes, int width) {
  if (width < 0 || width > lanes) throw std::invalid_argument("keep_first_lanes: width outside [0, lanes]");
  // Row r moves from r lanes to r width <= r lanes: copying the rows in ascending order never overwrites a
  // value before it is read.
  for (std::size_t r = 1; r < n_rows; ++r) std::copy_n(a.data() + r * lanes, width, a.data() + r * width);
  a.resize(n_rows * width);
}

}  // namespace

void LaneVectors::narrow(int width) {
  keep_first_lanes(re, rows, lanes, width);
  keep_first_lanes(im, rows, lanes, width);
  lanes = width;
}

BandedLanes::BandedLanes(int n_rows, int half_bandwidth, int n_lanes)
    : rows(n_rows),
      p(half_bandwidth),
      lanes(n_lanes),
      a(static_cast<std::size_t>(n_rows) * (2 * half_bandwidth + 1) * n_lanes, 0.0) {}

void BandedLanes::narrow(int width) {
  keep_first_lanes(a, static_cast<std::size_t>(rows) * (2 * p + 1), lanes, width);
  lanes = width;
}

BandedLanes BandedLanes::first_lanes(int width, int n_rows) const {
  if (width < 0 || width > lanes) throw std::invalid_argument("BandedLanes::first_lanes: width outside [0, lanes]");
  if (n_rows < 0) n_rows = rows;
  if (n_rows > rows) throw std::invalid_argument("BandedLanes::first_lanes: more rows than it has");
  BandedLanes narrow(n_rows, p, width);
  for (std::size_t row = 0; row < static_cast<std::size_t>(n_rows) * (2 * p + 1); ++row)
    std::copy_n(a.data() + row * lanes, width, narrow.a.data() + row * width);
  return narrow;
}

namespace {

constexpr int kMaxBandTerms = 15;

/// One row of y = A x (accumulate: y += scale A x) over lanes [0, m_end), the band terms k = k0..k1 summed in
/// that order from 0 for each lane (the bits of a sum kept per lane), K = k1 - k0 + 1 at compile time where
/// it is the full band, so that the terms unroll and the loop over the lanes vectorizes without a scratch row.
template <int K, bool kAccumulate>
__attribute__((always_inline)) inline void multiply_row(const double* const* a_k, const double* const* x_re,
                                                        const double* const* x_im, int n_k, double* __restrict y_re,
                                                        double* __restrict y_im, int m_end, double scale) {
  const int n = K > 0 ? K : n_k;
  for (int m = 0; m < m_end; ++m) {
    double s_re = 0, s_im = 0;
    for (int k = 0; k < n; ++k) {
      s_re += a_k[k][m] * x_re[k][m];
      s_im += a_k[k][m] * x_im[k][m];
    }
    if constexpr (kAccumulate) {
      y_re[m] += scale * s_re;
      y_im[m] += scale * s_im;
    } else {
      y_re[m] = s_re;
      y_im[m] = s_im;
    }
  }
}

}  // namespace

SLIDEWAVE_VECTOR_CLONES
void BandedLanes::multiply(const LaneVectors& x, LaneVectors& y, int r0, int r1, int m_end, bool accumulate,
                           double scale) const {
  if (2 * p + 1 > kMaxBandTerms) throw std::invalid_argument("BandedLanes::multiply: half-bandwidth above 7");
  const double *a_k[kMaxBandTerms], *x_re[kMaxBandTerms], *x_im[kMaxBandTerms];
  for (int r = r0; r < r1; ++r) {
    int n_k = 0;
    for (int k = std::max(-p, -r); k <= p && r + k < rows; ++k, ++n_k) {
      a_k[n_k] = a.data() + at(r, k, 0);
      x_re[n_k] = x.re.data() + x.at(r + k, 0);
      x_im[n_k] = x.im.data() + x.at(r + k, 0);
    }
    double* y_re = y.re.data() + y.at(r, 0);
    double* y_im = y.im.data() + y.at(r, 0);
    const bool full = n_k == 7;  // half-bandwidth 3 (Q4), away from the ends
    if (full && accumulate)
      multiply_row<7, true>(a_k, x_re, x_im, n_k, y_re, y_im, m_end, scale);
    else if (full)
      multiply_row<7, false>(a_k, x_re, x_im, n_k, y_re, y_im, m_end, scale);
    else if (accumulate)
      multiply_row<0, true>(a_k, x_re, x_im, n_k, y_re, y_im, m_end, scale);
    else
      multiply_row<0, false>(a_k, x_re, x_im, n_k, y_re, y_im, m_end, scale);
  }
}

namespace {

/// The band L D L^T of lane m's trailing block (rows and columns [first, A.rows)) into band (row r's entries
/// (r, r - p..r) at r (p + 1) + r - c; the unit diagonal's place holds D) and D. Returns the first pivot
/// that is not positive and finite (the factorization stops there), or -1.
int band_ldlt(const BandedLanes& A, int first, int m, std::vector<double>& band, std::vector<double>& D) {
  const int n = A.rows - first, p = A.p;
  const auto entry = [&band, p](int r, int c) -> double& { return band[r * (p + 1) + (r - c)]; };  // r-p <= c <= r
  for (int r = 0; r < n; ++r)
    for (int c = std::max(0, r - p); c <= r; ++c) entry(r, c) = A.get(first + r, c - r, m);
  for (int r = 0; r < n; ++r) {
    const int lowest = std::max(0, r - p);
    for (int c = lowest; c < r; ++c) {
      double v = entry(r, c);
      for (int q = lowest; q < c; ++q) v -= entry(r, q) * D[q] * entry(c, q);
      entry(r, c) = v / D[c];
    }
    double d = entry(r, r);
    for (int q = lowest; q < r; ++q) d -= entry(r, q) * entry(r, q) * D[q];
    D[r] = d;
    if (!(d > 0) || !std::isfinite(d)) return r;
  }
  return -1;
}

}  // namespace

BandedLaneFactor::BandedLaneFactor(const BandedLanes& A, int first)
    : first_(first), n_(A.rows - first), p_(A.p), lanes_(A.lanes) {
  const int n = n_, p = p_;
  L_.assign(static_cast<std::size_t>(n) * std::max(p, 1) * lanes_, 0.0);
  inv_D_.assign(static_cast<std::size_t>(n) * lanes_, 0.0);
  std::vector<double> band(static_cast<std::size_t>(n) * (p + 1)), D(n);
  for (int m = 0; m < lanes_; ++m) {
    const int failed = band_ldlt(A, first, m, band, D);
    if (failed >= 0) {
      std::ostringstream msg;
      msg << "BandedLaneFactor: lane " << m << " is not positive definite (pivot " << failed << " = " << D[failed]
          << ")";
      throw std::runtime_error(msg.str());
    }
    for (int r = 0; r < n; ++r) {
      inv_D_[static_cast<std::size_t>(r) * lanes_ + m] = 1.0 / D[r];
      for (int k = 1; k <= p && k <= r; ++k)
        L_[(static_cast<std::size_t>(r) * p + k - 1) * lanes_ + m] = band[r * (p + 1) + k];
    }
  }
}

void BandedLaneFactor::narrow(int width) {
  keep_first_lanes(L_, static_cast<std::size_t>(n_) * std::max(p_, 1), lanes_, width);
  keep_first_lanes(inv_D_, static_cast<std::size_t>(n_), lanes_, width);
  lanes_ = width;
}

std::vector<bool> positive_definite_lanes(const BandedLanes& A, int first) {
  const int n = A.rows - first;
  std::vector<double> band(static_cast<std::size_t>(n) * (A.p + 1)), D(n);
  std::vector<bool> definite(A.lanes);
  for (int m = 0; m < A.lanes; ++m) definite[m] = band_ldlt(A, first, m, band, D) < 0;
  return definite;
}

namespace {

/// One row of a sweep on both parts at once: x = x * scale (scale null: 1), then x -= l_k b_k for k < n_k,
/// in that order, per lane (the operations of a sweep that subtracts one band term at a time, with one pass
/// over the row instead of one per term and part). K = n_k at compile time for a full band.
template <int K>
__attribute__((always_inline)) inline void sweep_row(double* __restrict x_re, double* __restrict x_im,
                                                     const double* scale, const double* const* l,
                                                     const double* const* b_re, const double* const* b_im, int n_k,
                                                     int m_end) {
  const int n = K > 0 ? K : n_k;
  for (int m = 0; m < m_end; ++m) {
    double a_re = x_re[m], a_im = x_im[m];
    if (scale) {
      a_re *= scale[m];
      a_im *= scale[m];
    }
    for (int k = 0; k < n; ++k) {
      a_re -= l[k][m] * b_re[k][m];
      a_im -= l[k][m] * b_im[k][m];
    }
    x_re[m] = a_re;
    x_im[m] = a_im;
  }
}

}  // namespace

SLIDEWAVE_VECTOR_CLONES
void BandedLaneFactor::solve(LaneVectors& x, int m_end) const {
  // A real matrix: the real and imaginary parts are solved apart, in the same loops.
  const int p = p_, lanes = lanes_;
  if (p > kMaxBandTerms) throw std::invalid_argument("BandedLaneFactor::solve: half-bandwidth above 15");
  double* y_re = x.re.data() + x.at(first_, 0);
  double* y_im = x.im.data() + x.at(first_, 0);
  const double *l[kMaxBandTerms], *b_re[kMaxBandTerms], *b_im[kMaxBandTerms];
  const auto row = [lanes](double* y, int r) { return y + static_cast<std::size_t>(r) * lanes; };
  const auto sweep = [&](int r, const double* scale, int n_k) {
    if (n_k == 3)
      sweep_row<3>(row(y_re, r), row(y_im, r), scale, l, b_re, b_im, n_k, m_end);
    else
      sweep_row<0>(row(y_re, r), row(y_im, r), scale, l, b_re, b_im, n_k, m_end);
  };
  for (int r = 0; r < n_; ++r) {  // L y = b
    int n_k = 0;
    for (int k = 1; k <= p && k <= r; ++k, ++n_k) {
      l[n_k] = L_.data() + (static_cast<std::size_t>(r) * p + k - 1) * lanes;
      b_re[n_k] = row(y_re, r - k);
      b_im[n_k] = row(y_im, r - k);
    }
    if (n_k > 0) sweep(r, nullptr, n_k);
  }
  for (int r = n_ - 1; r >= 0; --r) {  // x = D^-1 y - L^T x
    int n_k = 0;
    for (int k = 1; k <= p && r + k < n_; ++k, ++n_k) {
      l[n_k] = L_.data() + (static_cast<std::size_t>(r + k) * p + k - 1) * lanes;
      b_re[n_k] = row(y_re, r + k);
      b_im[n_k] = row(y_im, r + k);
    }
    sweep(r, inv_D_.data() + static_cast<std::size_t>(r) * lanes, n_k);
  }
}

}  // namespace slidewave
