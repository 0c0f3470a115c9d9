#include "model/stick_phase/banded_lanes.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

namespace slidewave {

BandedLanes::BandedLanes(int n_rows, int half_bandwidth, int n_lanes)
    : rows(n_rows),
      p(half_bandwidth),
      lanes(n_lanes),
      a(static_cast<std::size_t>(n_rows) * (2 * half_bandwidth + 1) * n_lanes, 0.0) {}

void BandedLanes::multiply(const LaneVectors& x, LaneVectors& y, int r0, int r1, int m_end, bool accumulate,
                           double scale) const {
  std::vector<double> sum_re(m_end), sum_im(m_end);
  for (int r = r0; r < r1; ++r) {
    double* __restrict s_re = sum_re.data();
    double* __restrict s_im = sum_im.data();
    std::fill_n(s_re, m_end, 0.0);
    std::fill_n(s_im, m_end, 0.0);
    for (int k = std::max(-p, -r); k <= p && r + k < rows; ++k) {
      const double* a_k = a.data() + at(r, k, 0);
      const double* x_re = x.re.data() + x.at(r + k, 0);
      const double* x_im = x.im.data() + x.at(r + k, 0);
      for (int m = 0; m < m_end; ++m) {
        s_re[m] += a_k[m] * x_re[m];
        s_im[m] += a_k[m] * x_im[m];
      }
    }
    double* __restrict y_re = y.re.data() + y.at(r, 0);
    double* __restrict y_im = y.im.data() + y.at(r, 0);
    if (accumulate)
      for (int m = 0; m < m_end; ++m) {
        y_re[m] += scale * s_re[m];
        y_im[m] += scale * s_im[m];
      }
    else
      for (int m = 0; m < m_end; ++m) {
        y_re[m] = s_re[m];
        y_im[m] = s_im[m];
      }
  }
}

double BandedLanes::bilinear(const LaneVectors& x, const LaneVectors& y, int m_end, const double* weight) const {
  std::vector<double> per_lane(m_end, 0.0);
  double* __restrict sum = per_lane.data();
  const bool quadratic = &x == &y;  // x^H A x: the symmetric band's upper half twice, the diagonal once
  for (int r = 0; r < rows; ++r) {
    const double* xr_re = x.re.data() + x.at(r, 0);
    const double* xr_im = x.im.data() + x.at(r, 0);
    if (quadratic) {
      const double* d = a.data() + at(r, 0, 0);
      for (int m = 0; m < m_end; ++m) sum[m] += d[m] * (xr_re[m] * xr_re[m] + xr_im[m] * xr_im[m]);
      for (int k = 1; k <= p && r + k < rows; ++k) {
        const double* a_k = a.data() + at(r, k, 0);
        const double* y_re = x.re.data() + x.at(r + k, 0);
        const double* y_im = x.im.data() + x.at(r + k, 0);
        for (int m = 0; m < m_end; ++m) sum[m] += 2 * a_k[m] * (xr_re[m] * y_re[m] + xr_im[m] * y_im[m]);
      }
      continue;
    }
    for (int k = std::max(-p, -r); k <= p && r + k < rows; ++k) {
      const double* a_k = a.data() + at(r, k, 0);
      const double* y_re = y.re.data() + y.at(r + k, 0);
      const double* y_im = y.im.data() + y.at(r + k, 0);
      for (int m = 0; m < m_end; ++m)  // Re(conj(x) (a y))
        sum[m] += a_k[m] * (xr_re[m] * y_re[m] + xr_im[m] * y_im[m]);
    }
  }
  double total = 0;
  for (int m = 0; m < m_end; ++m) total += weight[m] * sum[m];
  return total;
}

BandedLaneFactor::BandedLaneFactor(const BandedLanes& A, int first)
    : first_(first), n_(A.rows - first), p_(A.p), lanes_(A.lanes) {
  const int n = n_, p = p_;
  L_.assign(static_cast<std::size_t>(n) * std::max(p, 1) * lanes_, 0.0);
  inv_D_.assign(static_cast<std::size_t>(n) * lanes_, 0.0);
  std::vector<double> band(static_cast<std::size_t>(n) * (p + 1));
  const auto entry = [&band, p](int r, int c) -> double& { return band[r * (p + 1) + (r - c)]; };  // r-p <= c <= r
  std::vector<double> D(n);
  for (int m = 0; m < lanes_; ++m) {
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
      if (!(d > 0) || !std::isfinite(d)) {
        std::ostringstream msg;
        msg << "BandedLaneFactor: lane " << m << " is not positive definite (pivot " << r << " = " << d << ")";
        throw std::runtime_error(msg.str());
      }
      D[r] = d;
      inv_D_[static_cast<std::size_t>(r) * lanes_ + m] = 1.0 / d;
      for (int k = 1; k <= p && k <= r; ++k)
        L_[(static_cast<std::size_t>(r) * p + k - 1) * lanes_ + m] = entry(r, r - k);
    }
  }
}

void BandedLaneFactor::solve(LaneVectors& x, int m_end) const {
  const int p = p_, lanes = lanes_;
  for (int part = 0; part < 2; ++part) {  // a real matrix: the real and imaginary parts apart
    double* y = (part ? x.im : x.re).data() + x.at(first_, 0);
    for (int r = 0; r < n_; ++r) {  // L y = b
      double* __restrict out = y + static_cast<std::size_t>(r) * lanes;
      for (int k = 1; k <= p && k <= r; ++k) {
        const double* l = L_.data() + (static_cast<std::size_t>(r) * p + k - 1) * lanes;
        const double* b = out - static_cast<std::size_t>(k) * lanes;
        for (int m = 0; m < m_end; ++m) out[m] -= l[m] * b[m];
      }
    }
    for (int r = n_ - 1; r >= 0; --r) {  // x = D^-1 y - L^T x
      double* __restrict out = y + static_cast<std::size_t>(r) * lanes;
      const double* d = inv_D_.data() + static_cast<std::size_t>(r) * lanes;
      for (int m = 0; m < m_end; ++m) out[m] *= d[m];
      for (int k = 1; k <= p && r + k < n_; ++k) {
        const double* l = L_.data() + (static_cast<std::size_t>(r + k) * p + k - 1) * lanes;
        const double* b = out + static_cast<std::size_t>(k) * lanes;
        for (int m = 0; m < m_end; ++m) out[m] -= l[m] * b[m];
      }
    }
  }
}

}  // namespace slidewave
