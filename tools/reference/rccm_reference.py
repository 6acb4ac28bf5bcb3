#!/usr/bin/python3
"""Independent reference computation of the RCCM interface benchmarks B1 and B2.

Shares no code with the C++ project. Sources of truth: shared/docs/MODEL.md (signs, law),
shared/docs/BENCHMARKS.md (geometry, mesh, loads) and config/b1.cfg, config/b2.cfg (numbers).

Method (deliberately different from the project's bipotential Uzawa + ARKODE):
  * bulk: plane-strain T3 elements, dense stiffness, static condensation onto the 66
    interface DOFs (Schur complement with the clamped interface), MODEL.md sections 1, 4;
  * time: backward (implicit) Euler in beta, fully coupled with the contact problem at the
    end of the step; the BE update of beta is solved in closed form per node for given
    interface displacements, and substituted into the equilibrium (MODEL.md section 6);
  * contact: primal semi-smooth Newton on the Alart-Curnier complementarity function
    (Signorini + Coulomb on the slip increment, mubar = mu (1 - beta)), exact Jacobian
    including the derivative of beta, backtracking line search, relative tolerance 1e-12
    (MODEL.md section 3);
  * error: the whole run is repeated with every step halved (N, 2N, 4N); the observed order
    is reported and the first-order Richardson extrapolation 2 Q_2N - Q_N is used.

Usage:  /usr/bin/python3 tools/reference/rccm_reference.py b1|b2 [--m M] [--levels L]
           [--out FILE]
  M      substeps per 0.01 s base interval on the coarsest level (default per benchmark)
  L      number of levels (runs with M, 2M, ..., 2^(L-1) M substeps); default 4
"""
import json
import os
import sys
import time

# one core: keep the BLAS single-threaded (must precede the numpy import)
for _v in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS"):
    os.environ.setdefault(_v, "1")

import numpy as np  # noqa: E402

# ----------------------------------------------------------------------------------------
# Benchmark data (BENCHMARKS.md, config/b1.cfg, config/b2.cfg). Units mm, N, MPa, s.
# ----------------------------------------------------------------------------------------
BENCHMARKS = {
    "b1": dict(L=50.0, H=2.5, nx=32, ny=2, E=6.9e4, nu=0.333,
               Cn=2.0e5, Ct=2.0e5, w=1.0e-6, alpha=1.0, mu=0.2, beta0=1.0, T=10.0,
               out_times=[3.571, 5.143, 10.0], watch=(0.0, 0.0), m_default=50),
    "b2": dict(L=50.0, H=25.0, nx=32, ny=16, E=6.9e4, nu=0.333,
               Cn=1.64, Ct=1.64, w=1.0e-3, alpha=1.0, mu=0.2, beta0=1.0, T=10.0,
               out_times=[2.143, 3.143, 3.571, 10.0], watch=(25.0, 0.0), m_default=10),
}
BASE_DT = 0.01          # base grid of recorded times (every 0.01 s), refined by substeps
NEWTON_TOL = 1e-12      # relative tolerance of the contact/adhesion Newton solve
NEWTON_MAXIT = 60


# ----------------------------------------------------------------------------------------
# 1. Bulk: mesh, plane-strain T3 stiffness (MODEL.md section 1)
# ----------------------------------------------------------------------------------------
def structured_mesh(L, H, nx, ny):
    """Nodes (i, j) -> id j*(nx+1)+i; each cell split along (i,j)-(i+1,j+1)."""
    xs = np.linspace(0.0, L, nx + 1)
    ys = np.linspace(0.0, H, ny + 1)
    X, Y = np.meshgrid(xs, ys)                 # shape (ny+1, nx+1), row j
    coords = np.column_stack([X.ravel(), Y.ravel()])
    tris = []
    for j in range(ny):
        for i in range(nx):
            n00 = j * (nx + 1) + i
            n10 = n00 + 1
            n01 = n00 + (nx + 1)
            n11 = n01 + 1
            tris.append((n00, n10, n11))       # lower-right triangle
            tris.append((n00, n11, n01))       # upper-left triangle
    return coords, np.array(tris, dtype=int)


def plane_strain_matrix(E, nu):
    c = E / ((1.0 + nu) * (1.0 - 2.0 * nu))
    return c * np.array([[1.0 - nu, nu, 0.0],
                         [nu, 1.0 - nu, 0.0],
                         [0.0, 0.0, (1.0 - 2.0 * nu) / 2.0]])


def assemble_stiffness(coords, tris, Dm, thickness=1.0):
    ndof = 2 * len(coords)
    K = np.zeros((ndof, ndof))
    for tri in tris:
        x = coords[tri, 0]
        y = coords[tri, 1]
        area2 = (x[1] - x[0]) * (y[2] - y[0]) - (x[2] - x[0]) * (y[1] - y[0])
        assert area2 > 0.0, "clockwise triangle"
        b = np.array([y[1] - y[2], y[2] - y[0], y[0] - y[1]]) / area2
        c = np.array([x[2] - x[1], x[0] - x[2], x[1] - x[0]]) / area2
        B = np.zeros((3, 6))
        B[0, 0::2] = b
        B[1, 1::2] = c
        B[2, 0::2] = c
        B[2, 1::2] = b
        ke = thickness * 0.5 * area2 * B.T @ Dm @ B
        dofs = np.ravel(np.column_stack([2 * tri, 2 * tri + 1]))
        K[np.ix_(dofs, dofs)] += ke
    return K


# ----------------------------------------------------------------------------------------
# 2. Interface kinematics: bottom edge, n = (0,1), t = (1,0), tributary lengths
# ----------------------------------------------------------------------------------------
def bottom_interface(coords, nx):
    nodes = np.arange(nx + 1)                  # j = 0 row
    x = coords[nodes, 0]
    a = np.zeros(nx + 1)
    seg = np.diff(x)
    a[:-1] += 0.5 * seg
    a[1:] += 0.5 * seg
    return nodes, x, a


# ----------------------------------------------------------------------------------------
# Problem set-up and static condensation onto the interface (MODEL.md section 4)
# ----------------------------------------------------------------------------------------
class Problem:
    def __init__(self, name):
        p = BENCHMARKS[name]
        self.name = name
        self.p = p
        coords, tris = structured_mesh(p["L"], p["H"], p["nx"], p["ny"])
        K = assemble_stiffness(coords, tris, plane_strain_matrix(p["E"], p["nu"]))
        self.coords = coords
        cnodes, self.x, self.a = bottom_interface(coords, p["nx"])
        self.m = len(cnodes)
        T = p["T"]
        tol = 1e-9
        # Prescribed DOFs with their rates value/T (linear ramps over [0, T]).
        pres = {}
        groups = {}
        if name == "b1":
            A = np.where((np.abs(coords[:, 0]) < tol) & (np.abs(coords[:, 1] - p["H"]) < tol))[0]
            assert len(A) == 1
            pres[2 * A[0] + 1] = 0.3 / T
            groups["A_y"] = [2 * A[0] + 1]
        else:
            left = np.where((np.abs(coords[:, 0]) < tol) & (coords[:, 1] > tol))[0]
            top = np.where(np.abs(coords[:, 1] - p["H"]) < tol)[0]
            for n in left:
                pres[2 * n] = 20.0 / T
            for n in top:
                pres[2 * n + 1] = -0.5 / T
            groups["left_x"] = [2 * n for n in left]
            groups["top_y"] = [2 * n + 1 for n in top]
        pdofs = np.array(sorted(pres))
        self.rate = np.array([pres[d] for d in pdofs])           # up(t) = t * rate
        cdofs = np.ravel(np.column_stack([2 * cnodes, 2 * cnodes + 1]))   # (t, n) per node
        ndof = K.shape[0]
        assert not set(cdofs) & set(pdofs)
        idofs = np.setdiff1d(np.arange(ndof), np.concatenate([cdofs, pdofs]))
        Kii = K[np.ix_(idofs, idofs)]
        Kic = K[np.ix_(idofs, cdofs)]
        Kip = K[np.ix_(idofs, pdofs)]
        L = np.linalg.cholesky(Kii)            # K_ii is SPD: the clamped interface holds it
        solve = lambda B: np.linalg.solve(L.T, np.linalg.solve(L, B))
        Xc = solve(Kic)
        Xp = solve(Kip)
        self.S = K[np.ix_(cdofs, cdofs)] - Kic.T @ Xc             # condensed stiffness
        self.S = 0.5 * (self.S + self.S.T)
        self.Hm = K[np.ix_(cdofs, pdofs)] - Kic.T @ Xp             # coupling to prescribed
        self.M = K[np.ix_(pdofs, pdofs)] - Kip.T @ Xp
        self.M = 0.5 * (self.M + self.M.T)
        # equilibrium on the interface: (S + D(beta)) u_c = b(t) + Rbar, b(t) = -H up(t)
        self.b1 = -self.Hm @ self.rate
        # reactions at prescribed DOFs: Rp = H^T u_c + M up(t). Group sums as
        # (h, m0, rate): sum_{d in g} Rp_d = h . u_c + m0 t; every DOF of a group has the
        # same rate, so the group's work increment is (sum R) * rate * dt.
        self.groups = {}
        self.group_dofs = groups
        for g, dl in groups.items():
            sel = np.isin(pdofs, dl).astype(float)
            rates = self.rate[sel > 0]
            assert np.allclose(rates, rates[0])
            self.groups[g] = (self.Hm @ sel, sel @ self.M @ self.rate, rates[0])
        self.pdofs = pdofs
        self.K, self.cdofs, self.idofs = K, cdofs, idofs
        wx, wy = p["watch"]
        self.watch = int(np.argmin(np.abs(self.x - wx)))
        assert abs(self.x[self.watch] - wx) < 1e-9 and abs(wy) < 1e-12
        self.Cv = np.array([p["Ct"], p["Cn"]])
        # augmentation parameter of the Alart-Curnier function (any r > 0 gives the same
        # solution; this one makes its two branches comparably scaled)
        dS = np.diag(self.S).reshape(self.m, 2)
        self.r = dS[:, 1] + self.a * p["Cn"]
        # block-diagonal index helpers
        i2 = np.arange(self.m)
        self.tr = 2 * i2
        self.nr = 2 * i2 + 1
        self.blk_r = np.repeat(np.arange(2 * self.m).reshape(self.m, 2), 2, axis=1).ravel()
        self.blk_c = np.tile(np.arange(2 * self.m).reshape(self.m, 2), (1, 2)).ravel()
        self.diag = np.arange(2 * self.m)

    def reaction(self, group, u, t):
        h, mr, _ = self.groups[group]
        return h @ u + mr * t

    def strain_energy(self, u, t):
        up = t * self.rate
        return 0.5 * (u @ self.S @ u + 2.0 * u @ (self.Hm @ up) + up @ self.M @ up)


def global_check(P, u, t, beta, Rbar):
    """Independent check of the condensation: rebuild the full displacement, verify
    K u = P^T r at all non-prescribed DOFs (r = Rbar + Radh, MODEL.md sec. 1/3) and return
    (relative equilibrium residual, reactions at prescribed DOFs from the full K)."""
    ndof = P.K.shape[0]
    full = np.zeros(ndof)
    full[P.pdofs] = t * P.rate
    full[P.cdofs] = u
    rhs = -(P.K[np.ix_(P.idofs, P.cdofs)] @ u + P.K[np.ix_(P.idofs, P.pdofs)] @ full[P.pdofs])
    full[P.idofs] = np.linalg.solve(P.K[np.ix_(P.idofs, P.idofs)], rhs)
    Ku = P.K @ full
    radh = -(P.a[:, None] * beta[:, None] ** 2 * P.Cv[None, :] * u.reshape(P.m, 2)).ravel()
    f = np.zeros(ndof)
    f[P.cdofs] = Rbar + radh
    free = np.setdiff1d(np.arange(ndof), P.pdofs)
    res = np.abs(Ku[free] - f[free]).max() / max(np.abs(Ku).max(), 1e-300)
    return res, Ku[P.pdofs]


# ----------------------------------------------------------------------------------------
# 3 + 6. One implicit step: RCCM law with backward-Euler beta, semi-smooth Newton
# ----------------------------------------------------------------------------------------
def beta_backward_euler(P, u, beta_n, dt):
    """MODEL.md sec. 3 ODE, backward Euler, solved exactly per node for given u:
    beta = beta_n - dt/alpha * (E beta - w)^+, E = Cn un^2 + Ct ut^2.
    If E beta_n <= w, beta = beta_n; else beta = (beta_n + k w)/(1 + k E) (< beta_n, > 0).
    Returns beta and d beta / d(u_t, u_n) (shape (m, 2))."""
    p = P.p
    U = u.reshape(P.m, 2)
    E = p["Ct"] * U[:, 0] ** 2 + p["Cn"] * U[:, 1] ** 2
    k = dt / p["alpha"]
    act = E * beta_n > p["w"]
    den = 1.0 + k * E
    beta = np.where(act, (beta_n + k * p["w"]) / den, beta_n)
    dbdE = np.where(act, -beta * k / den, 0.0)
    dbdu = (2.0 * dbdE)[:, None] * P.Cv[None, :] * U
    return beta, dbdu, E


def residual(P, u, t, dt, beta_n, ut_old, want_jac=True):
    """Alart-Curnier residual of the condensed interface problem at the end of a step.
    Rbar(u) = (S + D(beta(u))) u - b(t)   (equilibrium, MODEL.md sec. 4)
    normal:     F_n = Rbar_n - max(0, Rbar_n - r g),               g = u_n (g0 = 0)
    tangential: F_t = Rbar_t - clip(Rbar_t - r du_t, -B, B),     B = mu(1-beta) max(0, .)
    with du_t = u_t - u_t(last accepted) (MODEL.md sec. 3)."""
    p = P.p
    m = P.m
    beta, dbdu, E = beta_backward_euler(P, u, beta_n, dt)
    U = u.reshape(m, 2)
    ks = P.a[:, None] * beta[:, None] ** 2 * P.Cv[None, :]        # (m, 2) spring stiffness
    spring = (ks * U).ravel()                                      # = -Radh
    Su = P.S @ u
    bt = t * P.b1
    R = Su + spring - bt
    Rt, Rn = R[0::2], R[1::2]
    ut, un = U[:, 0], U[:, 1]
    r = P.r
    sn = Rn - r * un
    cont = sn > 0.0
    Lam = np.where(cont, sn, 0.0)
    mub = p["mu"] * (1.0 - beta)
    B = mub * Lam
    st = Rt - r * (ut - ut_old)
    stick = np.abs(st) < B
    F = np.empty(2 * m)
    F[0::2] = Rt - np.clip(st, -B, B)
    F[1::2] = Rn - Lam
    scale = max(np.abs(bt).max(), np.abs(Su).max(), np.abs(spring).max(), 1e-300)
    info = dict(beta=beta, R=R, spring=spring, cont=cont, stick=stick, scale=scale)
    if not want_jac:
        return F, None, info
    # dR/du = S + diag(ks) + block(2 a beta Cv u (x) dbeta/du)
    dR = P.S.copy()
    dR[P.diag, P.diag] += ks.ravel()
    v = (2.0 * P.a * beta)[:, None] * P.Cv[None, :] * U
    dR[P.blk_r, P.blk_c] += (v[:, :, None] * dbdu[:, None, :]).ravel()
    J = dR.copy()
    idx = np.arange(m)
    nr, tr = P.nr, P.tr
    # normal rows in contact: F_n = r u_n
    ncs = nr[cont]
    J[ncs, :] = 0.0
    J[ncs, ncs] = r[cont]
    # tangential rows
    sts = tr[stick]
    J[sts, :] = 0.0
    J[sts, sts] = r[stick]
    slip = ~stick
    if np.any(slip & (B > 0.0)) or np.any(slip & (Lam > 0.0)):
        s = np.sign(st)
        dLam = dR[nr, :].copy()
        dLam[idx, nr] -= r
        dLam *= cont[:, None]
        dB = mub[:, None] * dLam
        dB[idx, tr] -= p["mu"] * Lam * dbdu[:, 0]
        dB[idx, nr] -= p["mu"] * Lam * dbdu[:, 1]
        sl = np.where(slip)[0]
        J[tr[sl], :] -= s[sl, None] * dB[sl, :]
    return F, J, info


def solve_step(P, t, dt, beta_n, u_old, u_guess, stats):
    """Semi-smooth Newton with backtracking on ||F||; returns converged u and info."""
    ut_old = u_old[0::2]
    u = u_guess.copy()
    F, J, info = residual(P, u, t, dt, beta_n, ut_old)
    nF = np.abs(F).max()
    for it in range(NEWTON_MAXIT):
        if nF <= NEWTON_TOL * info["scale"]:
            stats["newton"] += it
            stats["max_newton"] = max(stats["max_newton"], it)
            stats["max_res"] = max(stats["max_res"], nF / info["scale"])
            return u, info, True
        du = np.linalg.solve(J, -F)
        lam = 1.0
        n2 = np.linalg.norm(F)
        while True:
            un = u + lam * du
            Fn_, Jn_, infon = residual(P, un, t, dt, beta_n, ut_old)
            if np.linalg.norm(Fn_) <= (1.0 - 1e-4 * lam) * n2 or lam < 1e-6:
                break
            lam *= 0.5
            stats["backtracks"] += 1
        u, F, J, info = un, Fn_, Jn_, infon
        nF = np.abs(F).max()
    return u, info, nF <= 1e-9 * info["scale"]


# ----------------------------------------------------------------------------------------
# Time loop (MODEL.md sec. 6, backward Euler) with energy bookkeeping (sec. 3)
# ----------------------------------------------------------------------------------------
def time_grid(P, msub):
    """Base grid: every 0.01 s plus the output times; each interval split into msub."""
    T = P.p["T"]
    base = np.round(np.arange(0.0, T + 0.5 * BASE_DT, BASE_DT), 12)
    base = np.unique(np.concatenate([base, P.p["out_times"]]))
    fine = [base[:1]]
    for t0, t1 in zip(base[:-1], base[1:]):
        fine.append(t0 + (t1 - t0) * np.arange(1, msub + 1) / msub)
    grid = np.concatenate(fine)
    grid[-1] = T
    return base, grid


def run(P, msub, verbose=True):
    p = P.p
    base, grid = time_grid(P, msub)
    is_base = np.isin(np.round(grid, 9), np.round(base, 9))
    m = P.m
    u = np.zeros(2 * m)
    u_prev = u.copy()
    beta = np.full(m, p["beta0"])
    Rbar = np.zeros(2 * m)
    stats = dict(newton=0, max_newton=0, max_res=0.0, backtracks=0, failures=0,
                 max_gap_viol=0.0, max_Rn_viol=0.0, max_compl=0.0, max_coulomb=0.0)
    groups = list(P.groups)
    react = {g: [P.reaction(g, u, 0.0)] for g in groups}
    W_ext = 0.0
    D_dam = 0.0
    D_fric = 0.0
    watch = P.watch
    wt = [0.0]; wbeta = [beta[watch]]; wradh = [0.0]
    rec = dict(t=[0.0], beta=[beta.copy()], u=[u.copy()], Rbar=[Rbar.copy()],
               react={g: [react[g][0]] for g in groups})
    t_prev = 0.0
    dt_prev = None
    t0 = time.time()
    for k in range(1, len(grid)):
        t = grid[k]
        dt = t - t_prev
        guess = u + (dt / dt_prev) * (u - u_prev) if dt_prev else u.copy()
        unew, info, ok = solve_step(P, t, dt, beta, u, guess, stats)
        if not ok:   # retry from the last accepted state
            unew, info, ok = solve_step(P, t, dt, beta, u, u.copy(), stats)
        if not ok:
            stats["failures"] += 1
            raise RuntimeError("Newton failed at t=%g" % t)
        bnew = info["beta"]
        Rnew = info["R"]
        if not np.all(np.isfinite(unew)):
            raise RuntimeError("non-finite state at t=%g" % t)
        # --- energy terms (trapezoid for work and friction, MODEL.md sec. 3)
        for g in groups:
            react[g].append(P.reaction(g, unew, t))
        D_dam += p["alpha"] * np.sum(P.a * (bnew - beta) ** 2) / dt
        D_fric += -np.sum(0.5 * (Rbar[0::2] + Rnew[0::2]) * (unew[0::2] - u[0::2]))
        # --- sanity of the accepted state (Signorini and Coulomb, MODEL.md sec. 3)
        gsc = max(np.abs(unew).max(), 1e-300)
        fsc = info["scale"]
        stats["max_gap_viol"] = max(stats["max_gap_viol"], max(0.0, -unew[1::2].min()) / gsc)
        stats["max_Rn_viol"] = max(stats["max_Rn_viol"], max(0.0, -Rnew[1::2].min()) / fsc)
        stats["max_compl"] = max(stats["max_compl"],
                                 np.abs(unew[1::2] * Rnew[1::2]).max() / (gsc * fsc))
        stats["max_coulomb"] = max(stats["max_coulomb"], max(0.0, np.max(
            np.abs(Rnew[0::2]) - p["mu"] * (1.0 - bnew) * np.maximum(Rnew[1::2], 0.0))) / fsc)
        assert np.all(bnew <= beta + 1e-15) and np.all(bnew >= 0.0)
        u_prev, u, beta, Rbar = u, unew, bnew, Rnew
        dt_prev = dt
        t_prev = t
        wt.append(t); wbeta.append(beta[watch])
        wradh.append(-P.a[watch] * beta[watch] ** 2 * p["Cn"] * u[2 * watch + 1])
        if is_base[k]:
            rec["t"].append(t); rec["beta"].append(beta.copy()); rec["u"].append(u.copy())
            rec["Rbar"].append(Rbar.copy())
            for g in groups:
                rec["react"][g].append(react[g][-1])
            if verbose and abs(t - round(t)) < 1e-9:
                print("  m=%d t=%5.2f  beta_watch=%.6f  newton/step=%.2f  cpu=%.1fs"
                      % (msub, t, beta[watch], stats["newton"] / k, time.time() - t0),
                      flush=True)
    # external work: trapezoid of reactions times prescribed increments (MODEL.md sec. 3)
    tt = np.array(wt)
    for g in groups:
        rg = np.array(react[g])
        W_ext += np.sum(0.5 * (rg[1:] + rg[:-1]) * np.diff(tt)) * P.groups[g][2]
    T = p["T"]
    psi = lambda b_, u_: np.sum(P.a * (0.5 * b_ ** 2 * (P.Cv[None, :] * u_.reshape(m, 2) ** 2)
                                        .sum(axis=1) - p["w"] * b_))
    res = dict(steps=len(grid) - 1, grid=tt, react={g: np.array(react[g]) for g in groups},
               watch_beta=np.array(wbeta), watch_Radh_n=np.array(wradh),
               rec_t=np.array(rec["t"]), rec_beta=np.array(rec["beta"]),
               rec_u=np.array(rec["u"]), rec_Rbar=np.array(rec["Rbar"]),
               rec_react={g: np.array(rec["react"][g]) for g in groups},
               W_ext=W_ext, D_dam=D_dam, D_fric=D_fric,
               E_strain=P.strain_energy(u, T),
               dpsi=psi(beta, u) - psi(np.full(m, p["beta0"]), np.zeros(2 * m)),
               stats=stats, cpu=time.time() - t0)
    res["balance"] = res["W_ext"] - (res["E_strain"] + res["dpsi"] + D_dam + D_fric)
    # independent check of the condensed equilibrium and of the reactions at T
    eq, Rp = global_check(P, u, T, beta, Rbar)
    rdiff = max(abs(P.reaction(g, u, T) - Rp[np.isin(P.pdofs, P.group_dofs[g])].sum())
                / max(abs(P.reaction(g, u, T)), 1e-300) for g in groups)
    stats["global_equilibrium_residual"] = eq
    stats["reaction_check"] = rdiff
    return res


# ----------------------------------------------------------------------------------------
# Post-processing: series on a common time grid, peak, Richardson extrapolation
# ----------------------------------------------------------------------------------------
def series_times(T):
    """Times of the reported curves: every 0.001 s up to 2 s (the peak, the first debonding),
    every 0.01 s after. All levels' grids contain them when msub is a multiple of 10."""
    a = np.round(np.arange(0.0, 2.0, 0.001), 9)
    b = np.round(np.arange(2.0, T + 1e-9, 0.01), 9)
    return np.concatenate([a, b])


def pick(grid, values, times):
    idx = np.searchsorted(grid, times - 1e-9)
    idx = np.minimum(idx, len(grid) - 1)
    assert np.all(np.abs(grid[idx] - times) < 1e-7), "series time not on the grid"
    return values[idx]


def peak(grid, f):
    """Discrete maximum refined by the parabola through its neighbours."""
    i = int(np.argmax(f))
    if 0 < i < len(f) - 1:
        t0, t1, t2 = grid[i - 1:i + 2]
        f0, f1, f2 = f[i - 1:i + 2]
        h = t1 - t0
        if abs(t2 - t1 - h) < 1e-9 * h:
            den = f0 - 2 * f1 + f2
            if den < 0:
                s = 0.5 * (f0 - f2) / den
                return f1 - 0.25 * (f0 - f2) * s, t1 + s * h
    return f[i], grid[i]


def summarize_level(P, res):
    """Quantities of one run, as arrays of fixed shape (compared across levels)."""
    p = P.p
    st = series_times(p["T"])
    q = {}
    rt = res["rec_t"]
    q["beta"] = np.array([res["rec_beta"][np.argmin(np.abs(rt - t))] for t in p["out_times"]])
    g0 = list(P.groups)[0]
    q["force"] = pick(res["grid"], res["react"][g0], st)
    if P.name == "b2":
        q["force_y"] = pick(res["grid"], res["react"]["top_y"], st)
    pk, tp = peak(res["grid"], res["react"][g0])
    q["peak_force"], q["peak_time"] = pk, tp
    q["watch_beta"] = pick(res["grid"], res["watch_beta"], st)
    q["watch_Radh_n"] = pick(res["grid"], res["watch_Radh_n"], st)
    q["external_work"] = res["W_ext"]
    q["damage_dissipation"] = res["D_dam"]
    q["friction_dissipation"] = res["D_fric"]
    q["strain_energy"] = res["E_strain"]
    q["interface_free_energy_change"] = res["dpsi"]
    q["balance"] = res["balance"]
    return q


def front_check(P, res):
    """Physics sanity (BENCHMARKS.md 'What the results must show'): beta starts at 1, never
    increases; in B1 it falls first at x = 0 and the debonded zone {beta < 0.5} is a
    growing prefix of the interface (a front advancing from x = 0)."""
    rb = res["rec_beta"]
    out = dict(beta_in_0_1=bool(np.all((rb >= 0.0) & (rb <= 1.0))),
               beta_non_increasing=bool(np.all(np.diff(rb, axis=0) <= 1e-15)))
    damaged = np.where(np.any(rb < 0.99, axis=1))[0]
    if len(damaged):
        k0 = damaged[0]
        out["first_damage_time"] = float(res["rec_t"][k0])
        out["first_damaged_nodes_x"] = P.x[rb[k0] < 0.99].tolist()
    count = (rb < 0.5).sum(axis=1)
    prefix = all(np.all(row[:c] < 0.5) for row, c in zip(rb, count))
    out["debonded_zone_is_prefix"] = bool(prefix)
    out["debonded_count_non_decreasing"] = bool(np.all(np.diff(count) >= 0))
    out["front_x_at"] = {("%g" % t): float(P.x[min(int(count[np.argmin(np.abs(res["rec_t"] - t))]),
                                                   P.m - 1)])
                         for t in [0.5, 1, 2, 3, 3.571, 4, 5, 5.143, 6, 7, 8, 9, 10]}
    return out


def maxabs(x):
    return float(np.max(np.abs(x)))


def richardson(levels, key):
    """levels: list of summaries with halved steps. First-order Richardson on the two
    finest levels; its error estimated by the change from the previous extrapolation."""
    Q = [np.asarray(l[key], dtype=float) for l in levels]
    if len(Q) < 3:
        return Q[-1], maxabs(Q[-1] - Q[-2]), None
    R_fine = 2.0 * Q[-1] - Q[-2]
    R_prev = 2.0 * Q[-2] - Q[-3]
    d1 = maxabs(Q[-2] - Q[-3])
    d2 = maxabs(Q[-1] - Q[-2])
    order = float(np.log2(d1 / d2)) if d2 > 0 and d1 > 0 else None
    return R_fine, maxabs(R_fine - R_prev), order


def method_sentence(P, msubs):
    return ("Independent numpy code: plane-strain T3, static condensation onto the 66 interface "
            "DOFs; each step solved fully implicitly (backward Euler in beta, solved in closed "
            "form per node and substituted into the equilibrium) with a primal semi-smooth "
            "Newton method on the Alart-Curnier function for Signorini + Coulomb (slip "
            "increment, mubar = mu(1-beta)), exact Jacobian, line search, relative tolerance "
            "1e-12; runs with %s substeps per 0.01 s (steps halved each time), values are the "
            "first-order Richardson extrapolation of the two finest runs, errors the change "
            "from the previous extrapolation." % ", ".join(str(m) for m in msubs))


def main(argv):
    name = argv[1] if len(argv) > 1 else "b1"
    P = Problem(name)
    msub = P.p["m_default"]
    nlev = 4
    out = None
    i = 2
    while i < len(argv):
        if argv[i] == "--m":
            msub = int(argv[i + 1]); i += 2
        elif argv[i] == "--levels":
            nlev = int(argv[i + 1]); i += 2
        elif argv[i] == "--out":
            out = argv[i + 1]; i += 2
        else:
            raise SystemExit("unknown argument " + argv[i])
    assert msub % 10 == 0, "msub must be a multiple of 10 (0.001 s series)"
    if out is None:
        here = os.path.dirname(os.path.abspath(__file__))
        out = os.path.join(here, "..", "..", "tests", "reference", name + ".json")
    msubs = [msub * 2 ** k for k in range(nlev)]
    levels, runs = [], []
    for ms in msubs:
        print("%s: run with %d substeps per 0.01 s" % (name, ms), flush=True)
        res = run(P, ms)
        s = summarize_level(P, res)
        levels.append(s)
        sanity = front_check(P, res)
        st = res["stats"]
        runs.append(dict(msub=ms, steps=res["steps"], cpu_s=round(res["cpu"], 1),
                         newton_per_step=st["newton"] / res["steps"],
                         max_newton=st["max_newton"], backtracks=st["backtracks"],
                         max_rel_residual=st["max_res"], max_gap_violation=st["max_gap_viol"],
                         max_Rn_violation=st["max_Rn_viol"],
                         max_complementarity=st["max_compl"],
                         max_coulomb_violation=st["max_coulomb"],
                         global_equilibrium_residual_at_T=st["global_equilibrium_residual"],
                         reaction_check_at_T=st["reaction_check"],
                         peak_force=s["peak_force"], peak_time=s["peak_time"],
                         external_work=s["external_work"],
                         damage_dissipation=s["damage_dissipation"],
                         friction_dissipation=s["friction_dissipation"],
                         strain_energy=s["strain_energy"],
                         interface_free_energy_change=s["interface_free_energy_change"],
                         energy_balance_residual=s["balance"],
                         beta_at_times=s["beta"].tolist(),
                         watch_beta_at_times=[float(s["beta"][k][P.watch])
                                              for k in range(len(P.p["out_times"]))],
                         force_at_T=float(s["force"][-1])))
        print("  steps=%d cpu=%.1fs newton/step=%.2f peak=%.6f at %.6f W=%.8g Ddam=%.8g "
              "Dfric=%.6g balance=%.3e" % (res["steps"], res["cpu"], runs[-1]["newton_per_step"],
                                           s["peak_force"], s["peak_time"], s["external_work"],
                                           s["damage_dissipation"], s["friction_dissipation"],
                                           s["balance"]), flush=True)
    st_t = series_times(P.p["T"])
    J = {"benchmark": name, "method": method_sentence(P, msubs), "steps": runs[-1]["steps"],
         "x": P.x.tolist(), "times": list(P.p["out_times"])}
    orders = {}
    beta, e, orders["beta"] = richardson(levels, "beta")
    beta = np.clip(beta, 0.0, 1.0)
    J["beta"] = beta.tolist()
    Qb = [l["beta"] for l in levels]
    J["beta_error"] = [maxabs((2 * Qb[-1][k] - Qb[-2][k]) - (2 * Qb[-2][k] - Qb[-3][k]))
                       if len(Qb) > 2 else maxabs(Qb[-1][k] - Qb[-2][k])
                       for k in range(len(P.p["out_times"]))]
    J["force_time"] = st_t.tolist()
    f, J["force_error"], orders["force"] = richardson(levels, "force")
    J["force"] = f.tolist()
    if name == "b2":
        fy, J["force_y_error"], orders["force_y"] = richardson(levels, "force_y")
        J["force_y"] = fy.tolist()
    if name == "b1":
        for k in ("peak_force", "peak_time"):
            v, J[k + "_error"], orders[k] = richardson(levels, k)
            J[k] = float(v)
    J["watch_time"] = st_t.tolist()
    wb, J["watch_beta_error"], orders["watch_beta"] = richardson(levels, "watch_beta")
    J["watch_beta"] = np.clip(wb, 0.0, 1.0).tolist()
    if name == "b1":
        wr, J["watch_Radh_n_error"], orders["watch_Radh_n"] = richardson(levels, "watch_Radh_n")
        J["watch_Radh_n"] = wr.tolist()
    for k in ("external_work", "damage_dissipation", "friction_dissipation"):
        v, J[k + "_error"], orders[k] = richardson(levels, k)
        J[k] = float(v)
    with open(out, "w") as fh:
        json.dump(J, fh, indent=1)
    # convergence evidence (per level) next to it
    lv = dict(benchmark=name, msub=msubs, observed_order=orders, runs=runs,
              physics_check_finest=sanity)
    print("physics check (finest run):", json.dumps(sanity))
    with open(out.replace(".json", "_levels.json"), "w") as fh:
        json.dump(lv, fh, indent=1)
    print("observed orders:", {k: (None if v is None else round(v, 3)) for k, v in orders.items()})
    print("wrote", out)


if __name__ == "__main__":
    main(sys.argv)
