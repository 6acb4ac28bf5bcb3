#include "rccm/fem/elastic_problem.hpp"

#include "rccm/base/errors.hpp"

#include <Eigen/Dense>

#include <algorithm>
#include <sstream>

namespace rccm {

ElasticProblem::ElasticProblem(const SparseMatrix& K, const SparseMatrix& springs, std::vector<int> prescribed,
                               const std::vector<int>& interface_dofs, const LinearSolverParams& linear)
    : prescribed_(std::move(prescribed)), free_index_(K.rows(), -1) {
  std::sort(prescribed_.begin(), prescribed_.end());
  std::vector<char> is_prescribed(K.rows(), 0);
  for (int d : prescribed_) is_prescribed[d] = 1;
  for (int d = 0; d < K.rows(); ++d)
    if (!is_prescribed[d]) {
      free_index_[d] = static_cast<int>(free_.size());
      free_.push_back(d);
    }
  std::vector<int> prescribed_index(K.rows(), -1);
  for (std::size_t k = 0; k < prescribed_.size(); ++k) prescribed_index[prescribed_[k]] = static_cast<int>(k);

  const SparseMatrix K0 = K + springs;
  std::vector<Eigen::Triplet<double>> ff, fd;
  for (int col = 0; col < K0.outerSize(); ++col)
    for (SparseMatrix::InnerIterator it(K0, col); it; ++it) {
      const int i = free_index_[it.row()];
      if (i < 0) continue;
      if (free_index_[col] >= 0)
        ff.emplace_back(i, free_index_[col], it.value());
      else
        fd.emplace_back(i, prescribed_index[col], it.value());
    }
  const int nf = static_cast<int>(free_.size()), nd = static_cast<int>(prescribed_.size());
  SparseMatrix K0_FF(nf, nf);
  K0_FF.setFromTriplets(ff.begin(), ff.end());
  K0_FD_.resize(nf, nd);
  K0_FD_.setFromTriplets(fd.begin(), fd.end());

  std::vector<int>& last = interface_free_;
  for (int d : interface_dofs)
    if (free_index_[d] >= 0) last.push_back(free_index_[d]);
  std::sort(last.begin(), last.end());
  last.erase(std::unique(last.begin(), last.end()), last.end());
  solver_ = make_spd_solver(K0_FF, linear, last);
  if (!last.empty()) trailing_ = dynamic_cast<const CholmodFactor*>(solver_.get());
  if (const auto* petsc = dynamic_cast<const PetscSolver*>(solver_.get())) inverse_ = petsc->interface_inverse();
  // A floating body gives a zero pivot or, in floating point, a tiny one; so do stiffnesses
  // that differ by more than double precision can hold (Cn = 1e30 against E = 1e3).
  if (!solver_->ok() || solver_->rcond() < 1e-14) {
    const Eigen::VectorXd d = Eigen::VectorXd(K0_FF.diagonal()).cwiseAbs();
    const double spread = d.maxCoeff() / std::max(d.minCoeff(), 1e-300);
    std::ostringstream m;
    m.precision(3);
    if (spread > 1e12)
      m << "the structure's stiffness is ill-conditioned (" << solver_->name() << ": rcond " << solver_->rcond()
        << "): its diagonal spans a factor " << spread << "; bring the stiffnesses closer: the interface's "
        << "a Cn and a Ct (interface.Cn and Ct times each contact node's length or area a, which the mesh's "
        << "size sets) against the body's material.E, or the materials among themselves";
    else
      m << "the structure is not restrained: its stiffness with the interface springs is singular (" << solver_->name()
        << ": rcond " << solver_->rcond()
        << "); add a prescribed displacement on a node set or an interface that holds the body";
    throw InputError(m.str());
  }
}

SparseMatrix ElasticProblem::interface_forces(const SparseMatrix& P, const std::vector<int>& order) const {
  std::vector<int> position(free_.size(), -1);
  for (std::size_t k = 0; k < order.size(); ++k) position[order[k]] = static_cast<int>(k);
  std::vector<Eigen::Triplet<double>> entries;
  for (int col = 0; col < P.outerSize(); ++col)
    for (SparseMatrix::InnerIterator it(P, col); it; ++it) {
      const int f = free_index_[col];
      if (f < 0) continue;  // a prescribed DOF: zero displacement under interface forces
      RCCM_VERIFY(position[f] >= 0, "flexibility(): P reads a DOF that was not ordered last");
      entries.emplace_back(position[f], static_cast<int>(it.row()), it.value());
    }
  SparseMatrix Pt(static_cast<Eigen::Index>(order.size()), P.rows());
  Pt.setFromTriplets(entries.begin(), entries.end());
  return Pt;
}

Eigen::MatrixXd ElasticProblem::flexibility(const SparseMatrix& P) const {
  if (inverse_) {  // P_C Z P_C^T, Z = (K0^-1)_CC
    const SparseMatrix Pt = interface_forces(P, interface_free_);
    const Eigen::MatrixXd ZPt = *inverse_ * Pt;
    return Pt.transpose() * ZPt;
  }
  if (!trailing_) return flexibility_products(P, Eigen::MatrixXd::Identity(P.rows(), P.rows()));
  Eigen::MatrixXd G = interface_forces(P, trailing_->trailing_order());  // P_C^T
  trailing_->trailing_factor().triangularView<Eigen::Lower>().solveInPlace(G);
  Eigen::MatrixXd W = Eigen::MatrixXd::Zero(P.rows(), P.rows());
  W.selfadjointView<Eigen::Lower>().rankUpdate(G.transpose());
  return W.selfadjointView<Eigen::Lower>();
}

Eigen::MatrixXd ElasticProblem::flexibility_products(const SparseMatrix& P, const Eigen::MatrixXd& Y) const {
  if (inverse_) {  // P_C (K0^-1)_CC P_C^T Y
    const SparseMatrix Pt = interface_forces(P, interface_free_);
    const Eigen::MatrixXd X = Pt * Y;
    return Pt.transpose() * (*inverse_ * X);
  }
  // By blocks of columns, the forces P^T Y gathered onto the free DOFs directly (the prescribed
  // ones: zero displacement, their forces unread). The blocks are as wide as 128 MB of forces
  // and displacements allow, 8 to 64 columns: wider blocks make the factor's solves matrix-matrix
  // products (B1 x32: setup 8.1 s with 8 columns, 5.3 s with 31).
  const Eigen::Index block =
      std::clamp<Eigen::Index>((Eigen::Index{1} << 27) / (16 * static_cast<Eigen::Index>(free_.size() + 1)), 8, 64);
  Eigen::MatrixXd out = Eigen::MatrixXd::Zero(P.rows(), Y.cols());
  for (Eigen::Index first = 0; first < Y.cols(); first += block) {
    const Eigen::Index k = std::min(block, Y.cols() - first);
    Eigen::MatrixXd f = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(free_.size()), k);
    for (int col = 0; col < P.outerSize(); ++col)
      for (SparseMatrix::InnerIterator it(P, col); it; ++it)
        if (free_index_[col] >= 0) f.row(free_index_[col]) += it.value() * Y.block(it.row(), first, 1, k);
    const Eigen::MatrixXd u = solver_->solve(f);
    for (int col = 0; col < P.outerSize(); ++col)
      for (SparseMatrix::InnerIterator it(P, col); it; ++it)
        if (free_index_[col] >= 0) out.block(it.row(), first, 1, k) += it.value() * u.row(free_index_[col]);
  }
  return out;
}

Eigen::MatrixXd ElasticProblem::restrict_free(const Eigen::MatrixXd& full) const {
  Eigen::MatrixXd out(free_.size(), full.cols());
  for (std::size_t i = 0; i < free_.size(); ++i) out.row(i) = full.row(free_[i]);
  return out;
}

Eigen::MatrixXd ElasticProblem::extend_free(const Eigen::MatrixXd& free) const {
  Eigen::MatrixXd out = Eigen::MatrixXd::Zero(free_index_.size(), free.cols());
  for (std::size_t i = 0; i < free_.size(); ++i) out.row(free_[i]) = free.row(i);
  return out;
}

Eigen::MatrixXd ElasticProblem::solve(const Eigen::MatrixXd& f, const Eigen::MatrixXd& u_prescribed) const {
  Eigen::MatrixXd uD(prescribed_.size(), u_prescribed.cols());
  for (std::size_t k = 0; k < prescribed_.size(); ++k) uD.row(k) = u_prescribed.row(prescribed_[k]);
  const Eigen::MatrixXd rhs = restrict_free(f) - K0_FD_ * uD;
  Eigen::MatrixXd u = extend_free(solver_->solve(rhs));
  for (std::size_t k = 0; k < prescribed_.size(); ++k) u.row(prescribed_[k]) = uD.row(k);
  return u;
}

}  // namespace rccm
