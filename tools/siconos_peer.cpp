#include "siconos_peer.hpp"

#include "rccm/base/errors.hpp"
#include "rccm/app/simulation.hpp"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>

// Siconos' C headers use C99 `restrict`.
#define restrict __restrict
extern "C" {
#include <siconos/numerics/FrictionContactProblem.h>
#include <siconos/numerics/Friction_cst.h>
#include <siconos/numerics/NonSmoothDrivers.h>
#include <siconos/numerics/NumericsMatrix.h>
#include <siconos/numerics/SolverOptions.h>
#include <siconos/numerics/SparseBlockMatrix.h>
#include <siconos/numerics/fc2d_compute_error.h>
#include <siconos/numerics/fc3d_compute_error.h>
#include <suitesparse/cs.h>  // the layout of Siconos' CSparseMatrix (cs_dl with SICONOS_INT64)
}
#undef restrict

namespace rccm::peer {

namespace {

/// Our index of Siconos' component k of a pair of `dim` components: Siconos puts the normal
/// first (n, t) / (n, t1, t2), we put it last (t, n) / (t1, t2, n).
int ours(int index, int dim) {
  const int k = index % dim;
  return index - k + (k == 0 ? dim - 1 : k - 1);
}

/// Siconos' order of v (ours), or ours of v (Siconos') with `back`.
Eigen::VectorXd swap_pairs(const Eigen::VectorXd& v, int dim, bool back = false) {
  Eigen::VectorXd out(v.size());
  for (int i = 0; i < v.size(); ++i) {
    if (back)
      out[ours(i, dim)] = v[i];  // v in Siconos' order
    else
      out[i] = v[ours(i, dim)];  // v in ours
  }
  return out;
}

Eigen::MatrixXd swap_pairs(const Eigen::MatrixXd& W, int dim) {
  Eigen::MatrixXd out(W.rows(), W.cols());
  for (int j = 0; j < W.cols(); ++j)
    for (int i = 0; i < W.rows(); ++i) out(i, j) = W(ours(i, dim), ours(j, dim));
  return out;
}

/// W in Siconos' storage, normal first: dense, or sparse by 2 x 2 blocks (its fc2d NSGS for
/// sparse problems, fc2d_nsgs_sbm; its driver aborts on compressed-column storage).
NumericsMatrix* to_siconos(const DelassusOperator& W, int dim) {
  const int n = static_cast<int>(W.size());
  if (const Eigen::MatrixXd* dense = W.dense()) {
    NumericsMatrix* M = NM_create(NM_DENSE, n, n);
    const Eigen::MatrixXd Ws = swap_pairs(*dense, dim);
    std::memcpy(M->matrix0, Ws.data(), sizeof(double) * n * n);
    return M;
  }
  RCCM_VERIFY(dim == 2, "sparse W for Siconos: 2D problems");
  const Eigen::SparseMatrix<double>& S = dynamic_cast<const SparseDelassus&>(W).matrix();
  NumericsMatrix* T = NM_create(NM_SPARSE, n, n);
  NM_triplet_alloc(T, S.nonZeros());
  for (int j = 0; j < n; ++j)
    for (Eigen::SparseMatrix<double>::InnerIterator it(S, j); it; ++it) NM_entry(T, int(it.row()) ^ 1, j ^ 1, it.value());
  NumericsMatrix* M = NM_create(NM_SPARSE_BLOCK, n, n);
  const int failed = SBM_from_csparse(2, NM_csc(T), M->matrix1);
  NM_free(T);
  if (failed) throw InputError("Siconos cannot store this W by 2 x 2 blocks");
  return M;
}

/// A Siconos problem owning copies of the data (normal first).
FrictionContactProblem* to_siconos(const PlainContactProblem& p) {
  const int n = static_cast<int>(p.q.size()), nc = n / p.dim;
  NumericsMatrix* M = to_siconos(*p.W, p.dim);
  auto* q = static_cast<double*>(std::malloc(sizeof(double) * n));
  auto* mu = static_cast<double*>(std::malloc(sizeof(double) * nc));
  const Eigen::VectorXd qs = swap_pairs(p.q, p.dim);
  std::memcpy(q, qs.data(), sizeof(double) * n);
  std::memcpy(mu, p.mu.data(), sizeof(double) * nc);
  return frictionContactProblem_new_with_data(p.dim, nc, M, q, mu);
}

int solver_id(const std::string& name, int dim) {
  if (dim == 3) {
    if (name == "nsgs") return SICONOS_FRICTION_3D_NSGS;
    if (name == "nsn") return SICONOS_FRICTION_3D_NSN_AC;
    throw InputError("unknown Siconos 3D solver '" + name + "' (nsgs, nsn)");
  }
  if (name == "nsgs") return SICONOS_FRICTION_2D_NSGS;
  if (name == "lemke") return SICONOS_FRICTION_2D_LEMKE;
  if (name == "enum") return SICONOS_FRICTION_2D_ENUM;
  throw InputError("unknown Siconos solver '" + name + "' (nsgs, lemke, enum)");
}

}  // namespace

PlainContactProblem read_dat(const std::string& path) {
  FILE* f = std::fopen(path.c_str(), "r");
  if (!f) throw InputError(path + ": cannot open");
  FrictionContactProblem* fc = frictionContact_newFromFile(f);
  std::fclose(f);
  if (!fc || fc->dimension != 2)
    throw InputError(path + ": not a 2D frictional contact problem in Siconos' .dat format");
  const int n = 2 * fc->numberOfContacts;
  PlainContactProblem p;
  if (fc->M->storageType == NM_SPARSE) {  // kept sparse: W is never densified for our solvers
    const CSparseMatrix* csc = NM_csc(fc->M);
    std::vector<Eigen::Triplet<double>> entries;
    entries.reserve(csc->p[n]);
    for (long j = 0; j < n; ++j)
      for (long k = csc->p[j]; k < csc->p[j + 1]; ++k)  // (n, t) -> (t, n): index ^ 1
        entries.emplace_back(int(csc->i[k] ^ 1), int(j ^ 1), csc->x[k]);
    Eigen::SparseMatrix<double> W(n, n);
    W.setFromTriplets(entries.begin(), entries.end());
    p.W = std::make_shared<SparseDelassus>(std::move(W));
  } else {
    Eigen::MatrixXd W(n, n);
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) W(i, j) = NM_get_value(fc->M, i, j);
    p.W = std::make_shared<DenseDelassus>(swap_pairs(W, 2));  // (n, t) and (t, n): the swap is its own inverse
  }
  p.q = swap_pairs(Eigen::Map<const Eigen::VectorXd>(fc->q, n).eval(), 2);
  p.mu = Eigen::Map<const Eigen::VectorXd>(fc->mu, fc->numberOfContacts);
  frictionContactProblem_free(fc);
  return p;
}

PeerSolution solve(const PlainContactProblem& p, const std::string& solver, double tolerance, int max_iterations) {
  FrictionContactProblem* fc = to_siconos(p);
  SolverOptions* options = solver_options_create(solver_id(solver, p.dim));
  options->iparam[SICONOS_IPARAM_MAX_ITER] = max_iterations;
  options->dparam[SICONOS_DPARAM_TOL] = tolerance;
  const int n = static_cast<int>(p.q.size());
  Eigen::VectorXd reaction = Eigen::VectorXd::Zero(n), velocity = Eigen::VectorXd::Zero(n);
  PeerSolution s;
  const auto start = std::chrono::steady_clock::now();
  s.info = p.dim == 3 ? fc3d_driver(fc, reaction.data(), velocity.data(), options)
                      : fc2d_driver(fc, reaction.data(), velocity.data(), options);
  s.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  s.iterations = options->iparam[SICONOS_IPARAM_ITER_DONE];
  s.R = swap_pairs(reaction, p.dim, true);
  solver_options_delete(options);
  frictionContactProblem_free(fc);
  s.error = error(p, s.R);
  return s;
}

double error(const PlainContactProblem& p, const Eigen::VectorXd& R) {
  FrictionContactProblem* fc = to_siconos(p);
  Eigen::VectorXd z = swap_pairs(R, p.dim);
  Eigen::VectorXd WR(R.size());
  p.W->multiply(R, WR);
  Eigen::VectorXd w = swap_pairs(Eigen::VectorXd(WR + p.q), p.dim);
  double e = 0;
  if (p.dim == 3) {
    SolverOptions* options = solver_options_create(SICONOS_FRICTION_3D_NSGS);
    fc3d_compute_error(fc, z.data(), w.data(), 1e-300, options, std::max(p.q.norm(), 1e-300), &e);
    solver_options_delete(options);
  } else {
    fc2d_compute_error(fc, z.data(), w.data(), 1e-300, std::max(p.q.norm(), 1e-300), &e);
  }
  frictionContactProblem_free(fc);
  return e;
}

std::vector<StepProblem> step_problems(const Model& model, const Config& cfg, int every) {
  std::vector<StepProblem> out;
  Eigen::VectorXd u_previous = Eigen::VectorXd::Zero(model.interface().layout.offset(model.contact_nodes()));
  Eigen::VectorXd Rbar_previous;
  RunOptions options;
  options.observer = [&](const AcceptedStep& a) {
    if (a.step > 0 && a.step % every == 0) {
      // The problem this step solved at commit: (t, beta), slip from the previous accepted state.
      const ContactProblem pb = model.contact_problem(a.t, a.state.beta, u_previous);
      out.push_back({a.step, a.t, pb, Rbar_previous, u_previous, plain_form(pb)});
    }
    u_previous = a.state.u;
    Rbar_previous = a.solution.Rbar;
  };
  Simulation(cfg, options).run();
  return out;
}

}  // namespace rccm::peer
