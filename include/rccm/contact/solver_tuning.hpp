// The tuning constants of the contact solvers, named and in one place. None changes a
// converged solution beyond the tolerance; each trades work against robustness, and the
// values are those measured best on B1, B2 and the Siconos problems (docs/PERFORMANCE.md).
#pragma once

namespace rccm::tuning {

// --- Bipotential solver (bipotential_solver.cpp) ---
/// Status patterns the exact-first phase tries from a warm start before any sweep.
constexpr int exact_first_patterns = 4;
/// Exact steps allowed during the sweeps of one solve, and the sweeps between two exact
/// steps of the same pattern.
constexpr int max_exact_steps = 10;
constexpr int exact_step_interval = 3;
/// Without a factorization at hand, an exact step is taken only when the sweeps still to go
/// exceed m / this (a dense factorization of m unknowns costs about m^3 / 3 products, a sweep
/// about m^2): measured on fc2d-bench, B1's cold steps need it, the granular flow does not.
constexpr double sweeps_per_factorization = 3;
/// Sweeps of one solve extrapolated by Anderson acceleration (solver.anderson); plain
/// sweeps beyond. Near round-off on a nonsmooth map the extrapolation can stall where the
/// plain sweeps still contract: the 1089-node corner peel at t = 9.05 (residual 6e-10 after
/// 2000 sweeps); accelerated solves there needed at most 93 sweeps.
constexpr int anderson_sweeps = 200;
/// The blocks of neighbouring pairs that a sweep passes over solver.block_sweeps times each
/// (la/hodlr.hpp SweepBlocks): at most this many rows (a compressed W0: its largest subtrees of
/// at most this many). The 2116-node corner peel (docs/PERFORMANCE.md "Block sweeps"), per
/// contact solve against single sweeps: subtrees of 198 rows swept twice 0.71, 396 rows 0.67,
/// 793 rows 0.73; the leaves (50 rows) three times 0.80.
constexpr long sweep_block_rows = 400;
/// Sweeps between two fresh products u = W0 y + q0: Gauss-Seidel's incremental updates of u
/// accumulate round-off; a product reads all of W0, as much as a sweep.
constexpr int refresh_interval = 8;
/// Convergence is judged on the sweeps' incremental u unless Anderson's extrapolations since
/// the last fresh product weigh more than this (their weights multiply the round-off of u,
/// ~1e-15 of |u| per sweep, measured): then on a fresh u.
constexpr double mixed_u_weight = 1e3;
/// Rbar = y - E u cancels where beta -> 0: its attainable accuracy is this many eps |y|.
constexpr double cancellation_floor = 1e3;
/// A pair's local predictor-corrector stops when its change falls below this fraction of
/// the solver tolerance (times the force level).
constexpr double local_tolerance_fraction = 0.1;
/// A pair's force level in its residual is at least this fraction of the largest force.
constexpr double residual_level_floor = 1e-8;
/// |det(I - W0_ii E_i)| below this: the pair has no stiffness left (an unrestrained body).
constexpr double singular_pair = 1e-12;
/// lambda_max of a pair's flexibility below this fraction of W0's diagonal: every component
/// of the pair is prescribed, its Rbar does not move it.
constexpr double prescribed_pair = 1e-14;

// --- The springs in K0 (model.cpp, solver.springs_follow_beta) ---
/// A pair's spring in K0 is at least this fraction of D(1) (beta^2 of the beta it is set at):
/// K0 stays regular where beta = 0. Late in the 625-node corner peel, K0's springs at the
/// damaged beta with this floor: 9.1 sweeps per solve (1e-3: 7.3, 1e-4: 7.0), at beta = 1:
/// 20.4. Below it, a body that only the debonded interface holds loses digits to cancellation
/// in u = W0 y + q0 (~1 / floor): at 1e-3 a block pressed onto a debonded base no longer
/// reached the tolerance 1e-10.
constexpr double springs_floor = 1e-2;
/// A pair's spring lags when beta^2 (floored) fell below 1 / this of its weight in W0; W0's
/// springs follow beta once this fraction of the pairs lag. The whole 625-node
/// peel (docs/PERFORMANCE.md): fractions 0.05 / 0.02 / 0.01 / 0.005 / 0.0025 condensed 1 / 3 /
/// 6 / 15 / 31 times for 12.0 / 8.2 / 6.8 / 5.8 / 5.3 sweeps per solve (13.6 never): 0.01 was fastest.
constexpr double springs_lag_ratio = 10;
constexpr double springs_lag_fraction = 0.01;
/// Then the springs follow beta on the pairs whose spring weighs more than this times its
/// weight at beta, and stay elsewhere: on the 625-node peel about 10 pairs a time instead of
/// 100-150 (all that beta moved), the same sweeps per solve (7.90 against 7.91).
constexpr double springs_follow_ratio = 2;
/// When the springs change on at most this fraction of the interface's components, W0 and q0
/// follow them by Woodbury's formula (Condensation::change_springs) instead of a new
/// factorization of K0 and a new condensation.
constexpr double springs_woodbury_fraction = 0.25;

// --- Exact active-set step (active_set.cpp) ---
/// Relative change of a row's spring (E) or of mubar left to refinement instead of a
/// low-rank correction.
constexpr double row_drift = 1e-3;
/// The same for a compressed W0, whose rows are refactorized in place (HodlrSolver::refactorize:
/// the changed leaves and the bisections above them) instead of corrected: a refinement step
/// (a compressed solve and product) costs more against it. B1 x16 (513 contact nodes, user
/// CPU, two runs each): 33.3 / 34.0 s at 1e-3, 25.3 / 25.7 at 1e-4, 22.9 / 22.5 at 1e-5,
/// 23.0 / 23.2 at 3e-6, 30.5 / 28.6 at 0.
constexpr double row_drift_compressed = 1e-5;
/// A 3D slide direction that turned by less than this (the distance of the unit vectors)
/// keeps its factorized rows: the turn is left to refinement, as a drift of E or mubar is.
constexpr double slide_direction_drift = 1e-2;
/// Changed rows kept as a pending Woodbury correction up to 1/fold_fraction of the rows;
/// folded into the inverse beyond; over half the rows: a new factorization.
constexpr int fold_fraction = 8;
/// Refinement steps with the corrected inverse, and the residual gain a step must make.
constexpr int refinement_steps = 6;
constexpr double refinement_gain = 0.1;
/// A correction smaller than this relative to y leaves y unmoved (converged); a residual
/// below this fraction of the first one is converged.
constexpr double unmoved = 1e-12;
constexpr double converged_residual = 1e-13;
/// W0 kept compressed (HODLR, from solver.compressed_min_nodes pairs on), for its products,
/// sweeps and the exact step's factorization: rows per leaf, and the accuracy of W0's
/// off-diagonal blocks relative to W0's diagonal.
constexpr int hodlr_leaf = 64;
constexpr double hodlr_accuracy = 1e-13;
/// The exact step's factorization is mixed from W0 truncated to this (HodlrMatrix::truncated),
/// a preconditioner: its refinement's products with W0 itself give the accurate solution.
/// B1 x16 (ranks 21 at 1e-13; user CPU, one run each beside other work): 21.6 s at 1e-13,
/// 19.3 at 1e-10 (rank 18), 17.4 at 1e-8 (15), 16.2 / 15.8 at 1e-6 (12), 17.3 at 1e-4 (9),
/// 15.2 at 1e-3 (7), 18.8 at 1e-2 (6): flat from 1e-6 to 1e-3, the safer end kept.
constexpr double hodlr_preconditioner_accuracy = 1e-6;
/// GMRES rescue of a stalled refinement: iterations, passes, relative tolerance.
constexpr int gmres_iterations = 30;
constexpr int gmres_passes = 3;
constexpr double gmres_tolerance = 1e-6;

}  // namespace rccm::tuning
