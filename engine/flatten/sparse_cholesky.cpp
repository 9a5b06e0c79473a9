// Sparse Cholesky backends behind one interface; see sparse_cholesky.hpp.
#include "engine/flatten/sparse_cholesky.hpp"

#include <Eigen/CholmodSupport>
#include <Eigen/SparseCholesky>
#include <variant>

#include "engine/core/engine_error.hpp"

namespace lastcut {
namespace {

using SpMat = Eigen::SparseMatrix<double>;
using EigenLdlt = Eigen::SimplicialLDLT<SpMat, Eigen::Lower, Eigen::AMDOrdering<int>>;
using CholmodAny = Eigen::CholmodDecomposition<SpMat, Eigen::Lower>;
using CholmodLdlt = Eigen::CholmodSimplicialLDLT<SpMat, Eigen::Lower>;
using CholmodLlt = Eigen::CholmodSupernodalLLT<SpMat, Eigen::Lower>;

// Measured on the 2-core shop-PC class machine with Debian's reference BLAS (docs/benchmarks-flatten.md):
// CHOLMOD's simplicial LDL^T with AMD factors as fast as Eigen's SimplicialLDLT and solves 1.5-3x faster,
// and ARAP does one factorization but ~30 solves. Supernodal gains nothing on 2D mesh Laplacians
// without an optimised BLAS; nested dissection (METIS) orders 5-7x slower than AMD for a small gain.
constexpr SparseSolver kFastestMeasured = SparseSolver::CholmodSimplicial;

template <class Cholmod>
void configure_cholmod(Cholmod& solver, FillOrdering ordering) {
  cholmod_common& common = solver.cholmod();
  common.nmethods = 1;
  common.method[0].ordering = ordering == FillOrdering::NestedDissection ? CHOLMOD_NESDIS : CHOLMOD_AMD;
  common.postorder = 1;
}

}  // namespace

std::string_view to_string(SparseSolver solver) {
  switch (solver) {
    case SparseSolver::Auto: return "auto";
    case SparseSolver::EigenLdlt: return "eigen-ldlt";
    case SparseSolver::Cholmod: return "cholmod";
    case SparseSolver::CholmodSimplicial: return "cholmod-simplicial";
    case SparseSolver::CholmodSupernodal: return "cholmod-supernodal";
  }
  return "unknown";
}

struct SparseCholesky::Impl {
  std::variant<EigenLdlt, CholmodAny, CholmodLdlt, CholmodLlt> solver;
};

SparseCholesky::SparseCholesky(SparseSolver solver, FillOrdering ordering)
    : impl_(std::make_unique<Impl>()), backend_(solver == SparseSolver::Auto ? kFastestMeasured : solver) {
  switch (backend_) {
    case SparseSolver::Auto:
    case SparseSolver::EigenLdlt: impl_->solver.emplace<EigenLdlt>(); break;
    case SparseSolver::Cholmod: configure_cholmod(impl_->solver.emplace<CholmodAny>(), ordering); break;
    case SparseSolver::CholmodSimplicial: configure_cholmod(impl_->solver.emplace<CholmodLdlt>(), ordering); break;
    case SparseSolver::CholmodSupernodal: configure_cholmod(impl_->solver.emplace<CholmodLlt>(), ordering); break;
  }
}

SparseCholesky::~SparseCholesky() = default;

void SparseCholesky::analyze_pattern(const SpMat& A) {
  std::visit([&](auto& s) { s.analyzePattern(A); }, impl_->solver);
}

void SparseCholesky::factorize(const SpMat& A) {
  const bool ok = std::visit(
      [&](auto& s) {
        s.factorize(A);
        return s.info() == Eigen::Success;
      },
      impl_->solver);
  if (!ok) {
    throw EngineError("sparse Cholesky factorization failed: the mesh has degenerate (zero-area) triangles");
  }
}

Eigen::MatrixXd SparseCholesky::solve(const Eigen::MatrixXd& B) const {
  return std::visit([&](const auto& s) -> Eigen::MatrixXd { return s.solve(B); }, impl_->solver);
}

}  // namespace lastcut
