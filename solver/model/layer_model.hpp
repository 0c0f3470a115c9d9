#pragma once
// The discrete periodic layer: mesh, global K and M, their partitions into free DOFs (rows j < n_y,
// numbered first) and top DOFs (row j = n_y, displacement-controlled), and the quasi-static stages.
#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <memory>
#include <vector>

#include "config/run_config.hpp"
#include "contact/coulomb_local.hpp"
#include "fem/assembly.hpp"
#include "linalg/linear_solver.hpp"
#include "linalg/split_solver.hpp"
#include "mesh/layer_mesh.hpp"
#include "time/hht_stepper.hpp"

namespace slidewave {

struct LayerModel {
  explicit LayerModel(const RunConfig& config);

  RunConfig config;
  DerivedConstants d;
  LayerMesh mesh;
  RowSparseMatrix K_fd, M_fd, M_top_rows;
  int n_free, n_top, n_contact_dofs;
  /// The deformable substrate as a layer in its mirrored frame (model/substrate.hpp); null: the rigid flat.
  std::shared_ptr<const LayerModel> substrate;
  /// Steps the stick phase and the slip phase in wavenumbers where they apply (model/stick_phase/
  /// stick_phase_run.hpp, slip_phase_run.hpp); false: every step plainly. Not a configuration key: both give
  /// the same solution to round-off, and the tests use plain stepping as the phases' oracle.
  bool steps_in_wavenumbers = true;

  enum class FreeBlock { stiffness, mass };

  /// K and M on all DOFs, assembled on first use: the default path multiplies by their rows without storing them
  /// (stiffness_product, free_mass_product, top_mass_product) and reads its spectral blocks off a few of them
  /// (spectral_rows).
  const RowSparseMatrix& K() const;
  const RowSparseMatrix& M() const;
  /// K u on all DOFs: the bits of K() * u.
  Eigen::VectorXd stiffness_product(const Eigen::Ref<const Eigen::VectorXd>& u) const;
  /// M_tt v_t, the top-top block of M times the top's values: the bits of M().bottomRightCorner(n_top, n_top) v_t.
  Eigen::VectorXd top_mass_product(const Eigen::Ref<const Eigen::VectorXd>& v_t) const;
  /// The rows of K or M that the spectral blocks are read from (linalg/block_circulant_solver.hpp,
  /// circulant_blocks_of_rows; model/stick_phase/wavenumber_blocks.hpp): on all DOFs, the rows of the nodes in
  /// mesh columns 0, 1 and n_x - 1 stored (every distinct row), the others empty; M() itself with the
  /// redistributed mass (which changes rows after the assembly).
  const RowSparseMatrix& spectral_rows(FreeBlock which) const;

  /// The free-free blocks in column-major storage (what CHOLMOD factorizes, and the plain step's K_eff), assembled
  /// on first use: a run on the default path never uses them (factorize(FreeBlock) reads K's and M's rows, and
  /// free_mass_product M's).
  const Eigen::SparseMatrix<double>& K_ff() const;
  const Eigen::SparseMatrix<double>& M_ff() const;
  /// M_ff in row-major storage (the plain step's products), assembled on first use like K_ff.
  const RowSparseMatrix& M_ff_rows() const;
  /// The blocks the plain HHT step works on (time/hht_stepper.hpp; assembles the free-free ones).
  PartitionedSystem partitioned() const;
  /// M_ff x_f, from M's rows: the bits of M_ff_rows() x_f.
  Eigen::VectorXd free_mass_product(const Eigen::Ref<const Eigen::VectorXd>& x_f) const;

  /// K_ff or M_ff factorized with the configured linear solver; `spectral` from the blocks of spectral_rows(which)
  /// (linalg/block_circulant_solver.hpp, circulant_blocks_of_rows), the same factors as from K_ff or M_ff.
  std::unique_ptr<LinearSolver> factorize(FreeBlock which) const;
  /// Factorizes a free-free matrix (K_eff, K_ff, M_ff) with the configured linear solver.
  std::unique_ptr<LinearSolver> factorize(const Eigen::SparseMatrix<double>& A) const;
  /// The same as a split solver whose loaded DOFs are the contact DOFs (what the HHT step needs).
  std::unique_ptr<SplitSolver> factorize_split(const Eigen::SparseMatrix<double>& A) const;

  /// Top DOF values for shear u_x and compression u_y.
  Eigen::VectorXd top_displacement(double u_x, double u_y) const;

 private:
  /// The rows of K and M as stencils (the redistributed mass: M's rows before the redistribution).
  std::shared_ptr<const UniformRows> stiffness_rows_, mass_rows_;
  RowSparseMatrix K_spectral_rows_, M_spectral_rows_;  ///< spectral_rows(); M's empty with the redistributed mass
  struct AssembledBlocks;  ///< K, M, K_ff, M_ff, M_ff_rows once assembled (shared by copies: they never change)
  std::shared_ptr<AssembledBlocks> assembled_;
};

/// Result of the quasi-static stages (1: compression, 2: shear until T/N = preshear_ratio * f).
struct PreloadState {
  Eigen::VectorXd u;            ///< all DOFs
  Eigen::VectorXd u_substrate;  ///< the substrate's DOFs (its mirrored frame), empty on a rigid flat
  Eigen::VectorXd r;            ///< contact reactions (2 per contact node: x, y)
  std::vector<ContactState> state;
  double u_x_top;  ///< top shear displacement of stage 2 (m)
  double T, N;     ///< forces per unit depth (N/m), T = -sum r_x, N = sum r_y
  int contact_iterations;
};

/// Solves stages 1 and 2 through the same contact law as the dynamics (slip measured from the
/// previous stage); with a substrate, on the pair's static Delassus operator (docs/substrate.md). Throws if the final
/// state is not all-closed, all-stick (all-closed if f = 0).
PreloadState solve_preload(const LayerModel& model);

}  // namespace slidewave
