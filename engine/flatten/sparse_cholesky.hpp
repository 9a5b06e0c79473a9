#pragma once
// One interface over the sparse Cholesky factorizations available as Debian packages: Eigen's
// SimplicialLDLT and SuiteSparse CHOLMOD (simplicial LDL^T, supernodal LL^T, or CHOLMOD's own choice).
// The symbolic analysis (fill-reducing ordering, elimination tree) is done once per sparsity pattern;
// numeric factorizations of matrices with that pattern reuse it. Which backend is fastest for our
// Laplacians is measured by bench/flatten (see docs/benchmarks-flatten.md) and decides SparseSolver::Auto.
#include <Eigen/Core>
#include <Eigen/SparseCore>
#include <memory>
#include <string_view>

namespace lastcut {

enum class SparseSolver {
  Auto,               // the fastest measured for mesh Laplacians on a shop PC (see sparse_cholesky.cpp)
  EigenLdlt,          // Eigen SimplicialLDLT, AMD ordering
  Cholmod,            // CHOLMOD, simplicial or supernodal as CHOLMOD decides
  CholmodSimplicial,  // CHOLMOD simplicial LDL^T
  CholmodSupernodal,  // CHOLMOD supernodal LL^T (BLAS-3 on dense blocks)
};

// Fill-reducing orderings CHOLMOD offers (Eigen's LDLT always uses AMD).
enum class FillOrdering { Amd, NestedDissection };

std::string_view to_string(SparseSolver solver);

class SparseCholesky {
 public:
  explicit SparseCholesky(SparseSolver solver = SparseSolver::Auto, FillOrdering ordering = FillOrdering::Amd);
  ~SparseCholesky();
  SparseCholesky(const SparseCholesky&) = delete;
  SparseCholesky& operator=(const SparseCholesky&) = delete;

  // A: n x n symmetric positive definite, both triangles stored (only the lower one is read).
  void analyze_pattern(const Eigen::SparseMatrix<double>& A);
  // Numeric factorization of a matrix with the analysed pattern. Throws EngineError if A is not
  // positive definite (e.g. a mesh with degenerate triangles).
  void factorize(const Eigen::SparseMatrix<double>& A);
  // X = A^-1 B for B n x k (the columns share the factor).
  Eigen::MatrixXd solve(const Eigen::MatrixXd& B) const;

  SparseSolver backend() const { return backend_; }

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
  SparseSolver backend_;
};

}  // namespace lastcut
