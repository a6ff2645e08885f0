"""Ledger: Sederberg's notes, chapter 11 (approximation: best constants, least-squares
B-spline fitting, fairing, interpolation constraints, constrained fairing)."""

from __future__ import annotations


import numpy as np
import sympy as sp
from gmpy2 import mpq

from exactcagd.toolbox import fitting as ft
from exactcagd.proofs import _ledger as L
from exactcagd.proofs._ledger import claim, not_checkable, erratum, verified

PTS = [[0, 0], [1, 2], [2, 3], [3, 3], [4, 2], [5, 0], [6, -1], [7, 0], [8, 1]]


def _setup(n_ctrl=6):
    ts = ft.parametrize(PTS)
    return ts, ft.knot_vector(ts, 3, n_ctrl)


@claim(doc="sederberg", section="11.1", ref="Examples 1, 2", statement="G = {2,3,3,5,7}: L2 best approximation 4 with e = 16; L-infinity best approximation 4.5 with e = 2.5")
def best_constants():
    assert ft.best_constant_l2([2, 3, 3, 5, 7]) == (4, 16)
    assert ft.best_constant_linf([2, 3, 3, 5, 7]) == (mpq(9, 2), mpq(5, 2))
    X = sp.Symbol("X", real=True)
    G = [2, 3, 3, 5, 7]
    assert sp.solve(sp.diff(sum((X - g) ** 2 for g in G), X), X) == [4]
    # L-infinity: max(|X - 2|, |X - 7|) is minimized where both are equal
    assert sp.solve(sp.Eq(X - 2, 7 - X), X) == [sp.Rational(9, 2)]
    return verified("exact values; sympy confirms the minimizers",
                    compared='printed L2 value 4 (e = 16) and L-infinity value 4.5 (e = 2.5) vs sympy: the zero of d/dX sum (X - g)^2 and the solution of X - 2 = 7 - X; exactcagd best_constant_l2/linf give the same exact values', reference='sympy')


@claim(doc="sederberg", section="11.2", ref="Lemma 11.2.1", statement="f(x) - f(x^) = sum[(x - x_i)^2 - (x^ - x_i)^2] = ... = n (x - x^)^2 >= 0")
def mean_lemma():
    n = 6
    xs = sp.symbols(f"x1:{n + 1}")
    X = sp.Symbol("x")
    xh = sum(xs) / n
    f = lambda v: sum((v - xi) ** 2 for xi in xs)  # noqa: E731
    lines = [
        sum((X - xi) ** 2 - (xh - xi) ** 2 for xi in xs),
        sum((X - xh) * (X + xh - 2 * xi) for xi in xs),
        (X - xh) * (n * X - sum(xs)),
        n * (X - xh) ** 2,
    ]
    assert all(sp.expand(f(X) - f(xh) - line) == 0 for line in lines)
    return verified("each line of the proof equals f(x) - f(x^) symbolically (n = 6)",
                    compared='each printed line of the proof vs sympy expansion of f(x) - f(x^) with symbolic x_1..x_6', reference='sympy')


@claim(doc="sederberg", section="11.3", ref="(11.1)-(11.3)", statement="dLsq/dT_j = 0 reduces to M_fit T = B with a_ij = sum_k B_i(s_k) B_j(s_k), b_i = sum_k P_k B_i(t_k)")
def normal_equations():
    ts, knots = _setup(5)
    N = ft.collocation_matrix(ts, knots, 3)
    T = sp.symbols("T0:5")
    y = [p[1] for p in PTS]
    Lsq = sum((sp.Rational(int(yk)) - sum(sp.Rational(int(N[k][j].numerator), int(N[k][j].denominator)) * T[j] for j in range(5))) ** 2 for k, yk in enumerate(y))
    sol = sp.solve([sp.diff(Lsq, Tj) for Tj in T], T, dict=True)[0]
    curve = ft.least_squares_fit(PTS, ts, knots, 3)
    assert [sol[Tj] for Tj in T] == [sp.Rational(int(p[1].numerator), int(p[1].denominator)) for p in curve.control_points]
    Mfit, B = ft.fitting_system(PTS, ts, knots, 3)
    Nn = np.array(N, dtype=object)
    assert np.all(Mfit == Nn.T.dot(Nn))
    return verified("sympy gradient of Lsq = 0 gives exactly the control points of the exact normal-equation solve (9 points, cubic, 5 control points)",
                    compared="printed (11.1)-(11.3) vs sympy: the zero of the gradient of Lsq (built from exactcagd's collocation values N_j(t_k)) equals exactcagd's normal-equation solve; M_fit = N^T N entrywise", reference='sympy')


@claim(doc="sederberg", section="11.3.1", ref="(11.4), (11.5)", statement="uniform t_j = (j-1)/(M-1); arc-length s_j = sum_{i<=j} |P_i - P_{i-1}| / sum |P_i - P_{i-1}|")
def parametrizations():
    assert ft.parametrize(PTS)[1] == mpq(1, 8)
    pts = [[0, 0], [3, 4], [3, 7], [15, 12]]  # chord lengths 5, 3, 13: exact
    assert ft.parametrize(pts, "chord") == [0, mpq(5, 21), mpq(8, 21), 1]
    chords = [sp.sqrt((b[0] - a[0]) ** 2 + (b[1] - a[1]) ** 2) for a, b in zip(pts, pts[1:])]  # (11.5) in sympy
    assert [sum(chords[:j]) / sum(chords) for j in range(4)] == [0, sp.Rational(5, 21), sp.Rational(8, 21), 1]
    assert [sp.Rational(j, 8) for j in range(9)] == [sp.Rational(str(v)) for v in ft.parametrize(PTS)]  # (11.4)
    irr = ft.parametrize([[0, 0], [1, 1], [2, 1]], "chord", inexact="float")
    assert abs(float(irr[1]) - 2**0.5 / (2**0.5 + 1)) < 1e-15
    return verified("exact uniform and chord-length parameters (rational chord lengths); irrational lengths are available "
                    "only as float lengths converted exactly (documented)",
                    compared='printed (11.4), (11.5) vs sympy: uniform j/8 and chord lengths with exact square roots (5, 3, 13 -> 0, 5/21, 8/21, 1) vs exactcagd parametrize; the irrational case vs sqrt 2 / (sqrt 2 + 1) in floats', reference='sympy')


@claim(doc="sederberg", section="11.3.2", ref="support", statement="the degree three B-spline with knot vector [s0, ..., s4] is zero outside [s0, s4]")
def support():
    knots = (0, 0, 0, 0, mpq(1, 5), mpq(2, 5), mpq(3, 5), mpq(4, 5), 1, 1, 1, 1)
    x = sp.Symbol("x")
    sym_knots = tuple(sp.Rational(str(k)) for k in knots)
    for j in range(len(knots) - 4):
        N = sp.bspline_basis(3, sym_knots, j, x)  # independent reference (sympy)
        for k in range(21):
            t = mpq(k, 20)
            v = ft.basis_values(knots, 3, t)[j]
            ref = N.subs(x, sp.Rational(k, 20))
            assert sp.Rational(str(v)) == ref
            if not (knots[j] <= t <= knots[j + 4]):
                assert v == 0 and ref == 0
    return verified("N_j(t) = 0 outside [k_j, k_{j+4}] at 21 exact parameters for all 8 cubic basis functions",
                    compared="printed support [s0, s4] vs sympy bspline_basis: exactcagd basis_values equal sympy's values at 21 exact parameters for all 8 cubic functions, both 0 outside [k_j, k_(j+4)]", reference='sympy')


@claim(doc="sederberg", section="11.4", ref="(11.6)", statement="min sum (P_i - sum T_j B_j(s_i))^2 + c int (sum T_j B_j(s))^2  (the item used is int f_ss^2)")
def fairing_energy():
    ts, knots = _setup()
    big = 10**6
    printed = ft.faired_fit(PTS, ts, knots, 3, big, derivative=0)
    second = ft.faired_fit(PTS, ts, knots, 3, big, derivative=2)
    # printed energy: the curve collapses towards the origin; f_ss energy: towards the least-squares line
    size_printed = max(abs(v) for p in printed.control_points for v in p)
    assert size_printed < mpq(1, 1000)
    line = ft.least_squares_fit(PTS, ts, (0, 0, 1, 1), 1)
    dist = max(abs(a - b) for t in ts for a, b in zip(second.evaluate(t), line.evaluate(t)))
    assert dist < mpq(1, 1000)
    def shrinks_towards_line(derivative):
        cv = ft.faired_fit(PTS, ts, knots, 3, big, derivative=derivative)
        d_ = max(abs(a_ - b_) for tt in ts for a_, b_ in zip(cv.evaluate(tt), line.evaluate(tt)))
        return None if d_ < mpq(1, 1000) else f"with c = 10^6 the fit is {float(d_):.3g} from the least-squares line (it shrinks to the origin)"
    return erratum(printed="c int (sum T_j B_j(s))^2", corrected="c int (sum T_j B_j''(s))^2 = c int f_ss^2",
                   detail=f"with c = 10^6 the printed energy shrinks the curve to the origin (max |T| = {float(size_printed):.1e}); "
                          f"the f_ss energy tends to the least-squares line (distance {float(dist):.1e}), the behaviour the text describes",
        printed_form=0, corrected_form=2, check=L.predicate(shrinks_towards_line), reference='independent-algorithm',
    )


@claim(doc="sederberg", section="11.4", ref="(11.7)", statement="(M_fit + c M_fair) T = B")
def fairing_system():
    ts, knots = _setup(5)
    c = mpq(1, 3)
    curve = ft.faired_fit(PTS, ts, knots, 3, c)
    T = sp.symbols("T0:5")
    N = ft.collocation_matrix(ts, knots, 3)
    F = ft.fairing_matrix(knots, 3)
    Q = lambda v: sp.Rational(int(v.numerator), int(v.denominator))  # noqa: E731
    y = [p[0] for p in PTS]
    E = sum((y[k] - sum(Q(N[k][j]) * T[j] for j in range(5))) ** 2 for k in range(len(PTS)))
    E += Q(c) * sum(Q(F[i, j]) * T[i] * T[j] for i in range(5) for j in range(5))
    sol = sp.solve([sp.diff(E, Tj) for Tj in T], T, dict=True)[0]
    assert [sol[Tj] for Tj in T] == [Q(p[0]) for p in curve.control_points]
    return verified("sympy minimization of the energy (with int f_ss^2 = T^T M_fair T) gives the exact solve of (11.7)",
                    compared="printed (11.7) vs sympy minimization of the energy sum (x_k - sum T_j N_j(t_k))^2 + c T^T M_fair T (collocation values and M_fair from exactcagd): its stationary point equals exactcagd's exact solve", reference='sympy')


@claim(doc="sederberg", section="11.4", ref="Algorithm 2", statement="midpoint rule with k = 10 on Support(B_iss) ∩ Support(B_jss) computes M_fair = [b_ij]")
def midpoint_algorithm():
    knots = (0, 0, 0, 0, mpq(1, 3), mpq(2, 3), 1, 1, 1, 1)
    exact = ft.fairing_matrix(knots, 3)
    approx = ft.midpoint_fairing_matrix(knots, 3, 10)
    diff = max(abs(a - b) for a, b in zip(exact.reshape(-1), approx.reshape(-1)))
    assert diff > 0 and exact[0, 0] == 324 and approx[0, 0] == mpq(32319, 100)
    return not_checkable(
        "the notes present Algorithm 2 as a quadrature (composite midpoint rule, k = 10) and never claim it is exact, "
        f"so its quadrature error is not an erratum (for reference: b_00 = {exact[0, 0]} exactly vs {approx[0, 0]} "
        f"({float(approx[0, 0]):.4f}), max entry error {float(diff):.3g}; exactcagd.fitting.fairing_matrix integrates exactly). "
        "The real defect of the printed algorithm, the doubled diagonal, is the row 'Algorithm 2 (diagonal)'"
    )


def _printed_algorithm_2(knots, degree, k, doubled):
    """Algorithm 2 transcribed from the notes, on sympy's B-spline basis; ``doubled`` keeps 'a_ij += d; a_ji += d' for i = j."""
    T = sp.Symbol("T")
    kn = tuple(sp.Rational(str(x)) for x in knots)
    n = len(kn) - degree - 1
    d2 = [sp.diff(sp.bspline_basis(degree, kn, i, T), T, 2) for i in range(n)]
    support = [(kn[i], kn[i + degree + 1]) for i in range(n)]
    A = sp.zeros(n, n)
    for i in range(n):
        for j in range(i, n):
            a, b = max(support[i][0], support[j][0]), min(support[i][1], support[j][1])
            d = 0
            if a < b:
                for i1 in range(1, 2 * k, 2):
                    x = a + sp.Rational(i1, 2 * k) * (b - a)
                    d += d2[i].subs(T, x) * d2[j].subs(T, x)
            d *= (b - a) / k
            A[i, j] += d
            if doubled or i != j:
                A[j, i] += d
    return A


@claim(doc="sederberg", section="11.4", ref="Algorithm 2 (diagonal)", statement="for i = 1..N, j = i..N: a_ij <- a_ji <- d <- 0; ...; a_ij += d; a_ji += d")
def midpoint_algorithm_diagonal():
    knots = (0, 0, 0, 0, sp.Rational(1, 3), sp.Rational(2, 3), 1, 1, 1, 1)
    T = sp.Symbol("T")
    kn = tuple(sp.Rational(str(x)) for x in knots)
    exact_diag = [sp.integrate(sp.diff(sp.bspline_basis(3, kn, i, T), T, 2) ** 2, (T, 0, 1)) for i in (0, 2)]

    def approximates_m_fair(doubled):
        A = _printed_algorithm_2(knots, 3, 10, doubled)
        for idx, i in enumerate((0, 2)):
            if abs(A[i, i] - exact_diag[idx]) > exact_diag[idx] / 50:
                return f"a_{i}{i} = {A[i, i]} ({float(A[i, i]):.2f}) vs int (B_{i}'')^2 = {exact_diag[idx]} (sympy)"
        return None

    return erratum(
        "a_ij += d; a_ji += d (for j = i the same entry receives d twice)",
        "a_ii += d once (add d to a_ji only for j != i)",
        "the algorithm as printed, run on sympy's B-spline basis (knots 0,0,0,0,1/3,2/3,1,1,1,1): its diagonal is about twice "
        "int (B_i'')^2 (sympy integration); with the diagonal added once the midpoint rule is within 2% of it",
        printed_form=True, corrected_form=False, check=L.predicate(approximates_m_fair),
    )


@claim(doc="sederberg", section="11.4.1", ref="Lagrange multipliers", statement="[[M_fit + c M_fair, A], [A^T, 0]] [T; lambda] = [B; C], a_ij = B_i(u_j)")
def interpolation_constraints():
    ts, knots = _setup(6)
    curve = ft.constrained_faired_fit(PTS, ts, knots, 3, 1, [0, mpq(1, 2), 1], [[0, 0], [4, 2], [8, 1]])
    assert curve.evaluate(0) == (0, 0) and curve.evaluate(mpq(1, 2)) == (4, 2) and curve.evaluate(1) == (8, 1)
    # stationarity of the Lagrangian gives 2(M T - B) + A lambda' = 0: the printed system with lambda = lambda'/2
    T, lam = sp.symbols("T0:3"), sp.symbols("l0:1")
    Mm = sp.Matrix([[2, 1, 0], [1, 3, 1], [0, 1, 2]])
    Bv = sp.Matrix([1, 2, 3])
    A = sp.Matrix([1, 1, 1])
    L = (sp.Matrix(T).T * Mm * sp.Matrix(T))[0] - 2 * (Bv.T * sp.Matrix(T))[0] + lam[0] * ((A.T * sp.Matrix(T))[0] - 5)
    sol = sp.solve([sp.diff(L, v) for v in T + lam], T + lam, dict=True)[0]
    K = sp.Matrix(sp.BlockMatrix([[Mm, A], [A.T, sp.zeros(1)]]))
    x = K.solve(sp.Matrix([Bv, sp.Matrix([5])]))
    assert [sol[v] for v in T] == list(x[:3])
    return verified("exact constrained fit interpolates its three points; the printed block system equals the Lagrangian stationarity (multiplier scaled by 1/2)",
                    compared="printed block system vs sympy stationarity of the Lagrangian on a 3x3 example (equal with the multiplier scaled by 1/2); exactcagd's constrained fit evaluated exactly at the three constraint parameters gives the prescribed points", reference='sympy')


@claim(doc="sederberg", section="11.4.2", ref="(11.11)", covers=["(11.9)", "(11.10)"], statement="X = [x1..xM]; H = [int B_i B_j]; A (2M x n), a_ij = a_(i+M)j = B_j(u_i); b_i = lx_i, b_(i+M) = -sx_i")
def box_qp_formulation():
    ts, knots = _setup(5)
    curve, cert = ft.box_constrained_fairing(PTS, ts, knots, 3, "axis", "1/2")
    for p, t in zip(PTS, ts):
        assert all(abs(a - b) <= mpq(1, 2) for a, b in zip(curve.evaluate(t), p))
    # printed signs: rows a_(i+M)j = +B_j(u_i) with b = -sx demand x(u_i) <= -sx_i, i.e. x(u_i) <= -(x_i - 1/2)
    i = 2
    lx, sx = PTS[i][0] + mpq(1, 2), PTS[i][0] - mpq(1, 2)
    assert sx > 0 and not (sx <= -sx)  # no value satisfies both sx <= x and the printed x <= -sx
    # very big boxes: the fairest curve under int f'' ^2 is a line (the notes' remark); under the printed H it is the zero curve
    line_curve, _ = ft.box_constrained_fairing(PTS, ts, knots, 3, "axis", 1000)
    G2 = ft.fairing_matrix(knots, 3)
    T = np.array(line_curve.control_points, dtype=object)
    assert all(T[:, k].dot(G2).dot(T[:, k]) == 0 for k in range(2))
    zero_curve, _ = ft.box_constrained_fairing(PTS, ts, knots, 3, "axis", 1000, derivative=0)
    assert all(v == 0 for p in zero_curve.control_points for v in p)
    def lower_rows_feasible(sign):
        # row a_(i+M) x <= b_(i+M) = -sx_i must say x(u_i) >= sx_i: with sign * x <= -sx this holds iff sign = -1
        return None if sign == -1 else f"x(u_i) <= -sx_i = {-sx} contradicts sx_i = {sx} <= x(u_i)"
    return erratum(printed="X = [x1..xM], H = int B_i B_j, a_(i+M)j = +B_j(u_i)",
                   corrected="X = [x1..xn] (control points), H = int B_i'' B_j'', a_(i+M)j = -B_j(u_i)",
                   detail="with the corrected data the exact QP (Lemke, KKT-certified) keeps every f(u_i) in its box; with the printed sign the lower "
                          "rows contradict the box; with huge boxes the f'' energy gives a straight line (zero energy) as the notes say, the "
                          "printed H gives the zero curve",
        printed_form=1, corrected_form=-1, check=L.predicate(lower_rows_feasible), reference='exact',
    )


@claim(doc="sederberg", section="11.4.2", ref="(11.12)", statement="frame boxes P_i + s t_i + t n_i, |s|, |t| <= 0.5: b_i = P_i.t_i + 0.5 t_i.t_i, b_(i+M) = -P_i.t_i + 0.5 t_i.t_i, ...")
def frame_boxes():
    ts, knots = _setup(5)
    curve, cert = ft.box_constrained_fairing(PTS, ts, knots, 3, "frame")
    tans, norms = ft.frame_boxes(PTS)
    for p, t, tv, nv in zip(PTS, ts, tans, norms):
        q = curve.evaluate(t)
        for v in (tv, nv):
            proj = sum((a - b) * c for a, b, c in zip(q, p, v))
            assert abs(proj) <= mpq(1, 2) * (v[0] ** 2 + v[1] ** 2)
    assert all(lam >= 0 for lam in cert["multipliers"])
    return verified(f"exact KKT-certified optimum with {len(cert['active'])} active box sides; every f(u_i) lies in its (unnormalized) tangent/normal box",
                    compared="printed frame-box constraints (11.12) vs exact projections computed in the check: every fitted point f(u_i) satisfies |(f(u_i) - P_i).v| <= |v|^2/2 for v = t_i, n_i (the printed b-vector itself is not re-derived; KKT multipliers from exactcagd's QP certificate are >= 0)", reference='exact')
