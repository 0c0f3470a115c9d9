#pragma once
// Products with a 2 x 2 block-circulant operator A of n nodes (the Delassus operator W of a periodic layer,
// or its inverse) by the convolution theorem, in O(n log n) instead of the dense O(n^2):
//     A(2i + a, 2k + b) = g_b(2 ((i - k) mod n) + a)      (g_b = A(:, b), the two columns of node 0)
// is a circular convolution per component pair, so with hats for the DFT over the node index,
//     (A r)^_a(m) = sum_b G_ab(m) r^_b(m),   G_ab(m) = DFT_j g_b(2j + a),
// one 2 x 2 complex matrix per wavenumber m = 0..n/2 (real data). A product is two real-to-complex FFTs,
// the 2 x 2 products and two complex-to-real FFTs (FFTW, plans made once). The inverse of A is
// block-circulant too, with G(m)^{-1} per wavenumber (inverse()).
//
// Round-off: the sums run in another order than a dense product's, so a result differs from it in the
// last bits (tested to round-off). FFTW runs with FFTW_ESTIMATE | FFTW_NO_SIMD, as in
// linalg/block_circulant_solver.hpp, so the numbers do not depend on timing or on the CPU's vector
// extensions.
//
// Not thread-safe: a product writes the object's work arrays.
#include <Eigen/Dense>
#include <complex>
#include <memory>
#include <vector>

namespace slidewave {

class BlockCirculantProduct {
 public:
  /// @param first_columns A(:, 0..1), 2n x 2, of a block-circulant A (n >= 1 nodes)
  explicit BlockCirculantProduct(const Eigen::MatrixXd& first_columns);
  ~BlockCirculantProduct();
  BlockCirculantProduct(BlockCirculantProduct&&) noexcept;
  BlockCirculantProduct& operator=(BlockCirculantProduct&&) noexcept;

  /// The product with A^{-1}, for an A whose every G(m) is Hermitian positive definite (a symmetric positive
  /// definite A); std::invalid_argument names the first wavenumber where it is not.
  BlockCirculantProduct inverse() const;

  /// y = q + A r (q, r, y of size 2n; y may be q).
  void residual(const Eigen::VectorXd& q, const Eigen::VectorXd& r, Eigen::VectorXd& y) const;
  /// y = A r.
  void apply(const Eigen::VectorXd& r, Eigen::VectorXd& y) const;

  int n_nodes() const { return n_; }

 private:
  BlockCirculantProduct(int n_nodes, std::vector<Eigen::Matrix2cd> spectrum);
  /// A r, in the work array out (valid until the next product): the spectrum of r, the 2 x 2 products with
  /// G(m) / n (FFTW's inverse is unnormalized), the inverse transform.
  const double* transform(const double* r) const;

  struct Plans;
  int n_;
  std::vector<Eigen::Matrix2cd> spectrum_;  ///< G(m), m = 0..n/2
  std::unique_ptr<Plans> plans_;
};

}  // namespace slidewave
