"""Chapter 11 of Sederberg's notes: approximation -- best constants, least-squares B-spline
fitting of points, fairing, interpolation constraints and box-constrained fairing, exact.

Source: Sederberg, CAGD notes (003), 11.1 examples 1-2, 11.2 Lemma 11.2.1, 11.3
least squares (11.1)-(11.3), parametrization (11.4)-(11.5), knot vectors (11.3.2), 11.4
fairing (11.6)-(11.7), 11.4.1 interpolation (Lagrange multipliers), 11.4.2 constrained
fairing (11.8)-(11.12).

All linear algebra is exact over Q (python-flint ``fmpq_mat``) when the data and the
parameters are rational.  Uniform parameters are rational; chord-length (and
centripetal) parameters are rational only when the chord lengths are: otherwise
:func:`parametrize` either refuses or (``inexact="float"``) uses the float lengths
converted exactly, which is then the documented source of inexactness.  The fairing
energy ``int (f'')^2`` is integrated exactly (Bernstein products per knot span), not by
the notes' midpoint rule (Algorithm 2, available as :func:`midpoint_fairing_matrix` for
comparison).  Box-constrained fairing solves a convex QP whose exact optimum is
certified by the KKT conditions (:mod:`exactcagd.toolbox._qp`).

>>> from exactcagd.toolbox.fitting import best_constant_l2, best_constant_linf
>>> best_constant_l2([2, 3, 3, 5, 7]), best_constant_linf([2, 3, 3, 5, 7])
((mpq(4,1), mpq(16,1)), (mpq(9,2), mpq(5,2)))
"""

from __future__ import annotations

import math

import numpy as np
from gmpy2 import mpq

from .. import limits
from ..errors import DimensionError, DomainError, InputError, KnotError, NotSupportedError
from ..exact import bernstein as bz
from ..exact import knots as kn
from ..exact.quadratic import sqrt_rational
from ..exact.scalars import to_count, to_rational, to_rational_array
from ..geometry.bspline import BSplineCurve
from . import _exact as ex
from . import _qp

__all__ = [
    "best_constant_l2",
    "best_constant_linf",
    "parametrize",
    "knot_vector",
    "basis_values",
    "collocation_matrix",
    "fitting_system",
    "gram_matrix",
    "fairing_matrix",
    "midpoint_fairing_matrix",
    "least_squares_fit",
    "faired_fit",
    "constrained_faired_fit",
    "box_constrained_fairing",
    "lsq_error",
    "frame_boxes",
]

_MPQ = type(mpq(0))


# ---------------------------------------------------------------- 11.1, 11.2
def best_constant_l2(values) -> tuple:
    """Example 1 / Lemma 11.2.1: the mean minimizes ``sum (x - x_i)^2``; returns ``(mean, error)``."""
    xs = [to_rational(v) for v in values]
    if not xs:
        raise InputError("no values")
    mean = sum(xs, mpq(0)) / len(xs)
    return mean, sum(((mean - x) ** 2 for x in xs), mpq(0))


def best_constant_linf(values) -> tuple:
    """Example 2: the midrange minimizes ``max |x - x_i|``; returns ``(midrange, error)``."""
    xs = [to_rational(v) for v in values]
    if not xs:
        raise InputError("no values")
    mid = (min(xs) + max(xs)) / 2
    return mid, (max(xs) - min(xs)) / 2


# ---------------------------------------------------------------- 11.3.1 parametrization
def _points(points) -> np.ndarray:
    P = to_rational_array(points, where="points")
    if P.ndim != 2 or P.shape[0] < 2:
        raise DimensionError("need at least two points (shape (M, d))")
    return P


def parametrize(points, method: str = "uniform", inexact: str = "raise") -> list:
    """Parameters in [0, 1] for the data points (notes 11.3.1).

    ``"uniform"`` (11.4): ``t_j = (j - 1)/(M - 1)``, exact.  ``"chord"`` (11.5, arc length
    of the polygon) and ``"centripetal"`` (square roots of the chord lengths): exact when
    every length (resp. its square root) is rational; otherwise ``inexact="raise"``
    (default) raises :class:`NotSupportedError` and ``inexact="float"`` computes the
    lengths in floating point and converts them exactly -- the parameters are then exact
    rationals close to, but not equal to, the true ones.
    """
    P = _points(points)
    M = P.shape[0]
    if method == "uniform":
        return [mpq(j, M - 1) for j in range(M)]
    if method not in ("chord", "centripetal"):
        raise InputError(f"unknown parametrization {method!r} (uniform, chord, centripetal)")
    if inexact not in ("raise", "float"):
        raise InputError("inexact must be 'raise' or 'float'")
    lengths = []
    for i in range(1, M):
        sq = sum(((a - b) ** 2 for a, b in zip(P[i], P[i - 1])), mpq(0))
        root = sqrt_rational(sq)
        if method == "centripetal" and isinstance(root, _MPQ):
            root = sqrt_rational(root)
        if isinstance(root, _MPQ):
            lengths.append(root)
        elif inexact == "float":
            val = math.sqrt(float(sq)) if method == "chord" else float(sq) ** 0.25
            lengths.append(to_rational(val))
        else:
            raise NotSupportedError(f"{method} parametrization: length between points {i - 1} and {i} is irrational "
                                    f"(sqrt({sq})); pass inexact='float' to use float lengths converted exactly")
    total = sum(lengths, mpq(0))
    if total == 0:
        raise DomainError("all points coincide")
    out, acc = [mpq(0)], mpq(0)
    for L in lengths:
        acc += L
        out.append(acc / total)
    return out


# ---------------------------------------------------------------- 11.3.2 knot vectors
def knot_vector(params, degree: int, n_ctrl: int, method: str = "average") -> tuple:
    """Clamped knot vector (standard convention, ``n_ctrl + degree + 1`` knots) on [t_0, t_M].

    ``"uniform"``: evenly spaced interior knots.  ``"subset"`` (notes 11.3.2): every
    ``m``-th parameter, ``m = M / (n_int + 1)``.  ``"average"``: de Boor's averaging
    ``u_j = (1 - a) t_{i-1} + a t_i``, ``i = floor(j d)``, ``a = j d - i``, ``d = M / (n_int + 1)``
    (interior knots always separated by data: good for the Schoenberg-Whitney condition).
    """
    ts = [to_rational(t) for t in params]
    if n_ctrl < degree + 1:
        raise KnotError(f"{n_ctrl} control points are too few for degree {degree}")
    n_int = n_ctrl - degree - 1
    a, b = ts[0], ts[-1]
    if a >= b:
        raise DomainError("parameters must increase from first to last")
    M = len(ts)
    if method == "uniform":
        inner = [a + (b - a) * mpq(j, n_int + 1) for j in range(1, n_int + 1)]
    elif method == "subset":
        m = M // (n_int + 1)
        if m < 1:
            raise KnotError("too many control points for the number of parameters")
        inner = [ts[j * m] for j in range(1, n_int + 1)]
    elif method == "average":
        d = mpq(M, n_int + 1)
        inner = []
        for j in range(1, n_int + 1):
            i = int(math.floor(j * d))
            alpha = j * d - i
            inner.append((1 - alpha) * ts[i - 1] + alpha * ts[min(i, M - 1)])
    else:
        raise InputError(f"unknown knot method {method!r} (uniform, subset, average)")
    knots = tuple([a] * (degree + 1) + inner + [b] * (degree + 1))
    return kn.check_knots(knots, n_ctrl, degree)


# ---------------------------------------------------------------- basis and matrices
def _identity(n):
    out = np.empty((n, n), dtype=object)
    for i in range(n):
        for j in range(n):
            out[i, j] = mpq(1 if i == j else 0)
    return out


def basis_values(knots, degree: int, t) -> list:
    """All ``N_j(t)``, ``j = 0..n-1`` (exact; de Boor's algorithm on the identity control points)."""
    knots = tuple(to_rational(k) for k in knots)
    n = len(knots) - degree - 1
    return list(kn.de_boor(_identity(n), knots, degree, to_rational(t)))


def collocation_matrix(params, knots, degree: int) -> list:
    """``N[k][j] = N_j(t_k)``."""
    return [basis_values(knots, degree, t) for t in params]


def fitting_system(points, params, knots, degree: int) -> tuple:
    """(11.3): ``M_fit = N^T N`` (``a_ij = sum_k B_i(s_k) B_j(s_k)``) and ``B = N^T P``."""
    P = _points(points)
    if len(params) != P.shape[0]:
        raise DimensionError("one parameter per point")
    N = np.array(collocation_matrix(params, knots, degree), dtype=object)
    return N.T.dot(N), N.T.dot(P)


def _bernstein_gram(q: int) -> np.ndarray:
    """``int_0^1 B^q_k B^q_l = C(q,k) C(q,l) / ((2q+1) C(2q, k+l))``."""
    G = np.empty((q + 1, q + 1), dtype=object)
    for k in range(q + 1):
        for l_ in range(q + 1):
            G[k, l_] = mpq(bz.binomial(q, k) * bz.binomial(q, l_), (2 * q + 1) * bz.binomial(2 * q, k + l_))
    return G


def gram_matrix(knots, degree: int, derivative: int = 0) -> np.ndarray:
    """Exact ``G_ij = int N_i^(r) N_j^(r) dt`` over the spline domain (``r = derivative``).

    The basis functions are the coordinates of the B-spline curve with identity control
    points; per knot span its Bézier form, differentiated ``r`` times (scaled by
    ``1/(b - a)`` each), gives ``G += (b - a) C^T G_q C`` with the Bernstein Gram matrix
    ``G_q`` -- one exact mechanism (Bernstein products, notes 9.3 / 2.15).
    """
    if isinstance(knots, (str, bytes, bytearray)) or not hasattr(knots, "__len__"):
        raise KnotError(f"knots: expected a sequence of numbers, got {type(knots).__name__}")
    degree, derivative = to_count(degree, where="degree"), to_count(derivative, where="derivative order")
    n = len(knots) - degree - 1
    if n < 1:
        raise KnotError(f"knots: {len(knots)} knots leave no basis function of degree {degree}")
    limits.check("max_control_points", n * n, f"gram_matrix: {n} x {n} entries")
    knots = tuple(to_rational(k, where=f"knots[{i}]") for i, k in enumerate(knots))
    spline = BSplineCurve(_identity(n), knots)
    G = np.empty((n, n), dtype=object)
    G[...] = mpq(0)
    for (a, b), piece in spline.to_bezier():
        C = piece.points_array()
        for _ in range(derivative):
            C = bz.derivative(C) / (b - a)
        q = C.shape[0] - 1
        if derivative > degree:
            continue
        G = G + (b - a) * C.T.dot(_bernstein_gram(q)).dot(C)
    return G


def fairing_matrix(knots, degree: int, derivative: int = 2) -> np.ndarray:
    """``M_fair = [int B_i'' B_j'']`` exactly (notes 11.4; ``derivative`` selectable)."""
    return gram_matrix(knots, degree, derivative)


def midpoint_fairing_matrix(knots, degree: int, k: int = 10) -> np.ndarray:
    """The notes' Algorithm 2: midpoint rule with ``k`` nodes on ``[a, b] = supp B_i'' ∩ supp B_j''``.

    Provided to compare with the exact :func:`fairing_matrix` (it is an approximation).
    """
    knots = tuple(to_rational(x) for x in knots)
    n = len(knots) - degree - 1
    spline = BSplineCurve(_identity(n), knots)
    second = []
    pieces = spline.to_bezier()
    def d2(t):
        for (a, b), piece in pieces:
            if a <= t <= b:
                C = bz.derivative(bz.derivative(piece.points_array())) / (b - a) ** 2
                return bz.de_casteljau(C, (t - a) / (b - a))
        raise DomainError("outside the domain")  # pragma: no cover
    del second
    lo, hi = knots[degree], knots[-degree - 1]
    G = np.empty((n, n), dtype=object)
    G[...] = mpq(0)
    for i in range(n):
        for j in range(i, n):
            a, b = max(knots[i], knots[j], lo), min(knots[i + degree + 1], knots[j + degree + 1], hi)
            if a >= b:
                continue
            d = mpq(0)
            for i1 in range(1, 2 * k, 2):
                x = a + i1 * (b - a) / (2 * k)
                v = d2(x)
                d += v[i] * v[j]
            d *= (b - a) / k
            G[i, j] = G[j, i] = d
    return G


# ---------------------------------------------------------------- fits
def _solve_fit(matrix, rhs, what):
    try:
        return ex.solve(matrix.tolist(), rhs.tolist(), what)
    except InputError as exc:
        raise InputError(f"{exc}: choose knots so that every basis function's support holds data "
                         "(Schoenberg-Whitney condition) or add fairing") from None


def least_squares_fit(points, params, knots, degree: int) -> BSplineCurve:
    """Minimize ``Lsq = sum_i |P_i - sum_j T_j B_j(t_i)|^2`` (11.1)-(11.3), exactly."""
    Mfit, B = fitting_system(points, params, knots, degree)
    T = _solve_fit(Mfit, B, "least-squares fit")
    return BSplineCurve(T, knots)


def faired_fit(points, params, knots, degree: int, c, derivative: int = 2) -> BSplineCurve:
    """(11.6)-(11.7): ``(M_fit + c M_fair) T = B`` with the exact energy ``int (f'')^2``."""
    c = to_rational(c, where="c")
    if c < 0:
        raise DomainError("the fairing constant must be >= 0")
    Mfit, B = fitting_system(points, params, knots, degree)
    T = _solve_fit(Mfit + c * fairing_matrix(knots, degree, derivative), B, "faired fit")
    return BSplineCurve(T, knots)


def constrained_faired_fit(points, params, knots, degree: int, c, interp_params, interp_points, derivative: int = 2) -> BSplineCurve:
    """11.4.1: faired fit through ``Q_k`` at ``u_k``, by Lagrange multipliers:
    ``[[M_fit + c M_fair, A], [A^T, 0]] [T; lambda] = [B; Q]`` with ``A_ik = B_i(u_k)``."""
    c = to_rational(c, where="c")
    Mfit, B = fitting_system(points, params, knots, degree)
    H = Mfit + c * fairing_matrix(knots, degree, derivative)
    Q = to_rational_array(interp_points, where="interp_points")
    if Q.ndim != 2 or Q.shape[1] != B.shape[1] or Q.shape[0] != len(interp_params):
        raise DimensionError("interp_points: one point (of the data's dimension) per interpolation parameter")
    A = np.array(collocation_matrix(interp_params, knots, degree), dtype=object).T  # n x I
    n, m = H.shape[0], A.shape[1]
    K = np.empty((n + m, n + m), dtype=object)
    K[...] = mpq(0)
    K[:n, :n] = H
    K[:n, n:] = A
    K[n:, :n] = A.T
    rhs = np.concatenate([B, Q], axis=0)
    sol = _solve_fit(K, rhs, "constrained faired fit")
    return BSplineCurve(sol[:n], knots)


def frame_boxes(points) -> tuple:
    """Tangent/normal estimates of 11.4.2: ``t_i ~ P_{i+1} - P_{i-1}`` (with ``P_0 = P_1``,
    ``P_{M+1} = P_M``), ``n_i`` perpendicular; exact rational, not normalized (planar)."""
    P = _points(points)
    if P.shape[1] != 2:
        raise DimensionError("frame boxes are planar")
    M = P.shape[0]
    tans, norms = [], []
    for i in range(M):
        a, b = P[max(i - 1, 0)], P[min(i + 1, M - 1)]
        tv = (b[0] - a[0], b[1] - a[1])
        if tv == (0, 0):
            raise DomainError(f"point {i}: neighbours coincide, no tangent estimate")
        tans.append(tv)
        norms.append((-tv[1], tv[0]))
    return tans, norms


def box_constrained_fairing(points, params, knots, degree: int, boxes: str = "axis", half_width="1/2",
                            derivative: int = 2) -> tuple[BSplineCurve, dict]:
    """11.4.2: the fairest spline whose value at each ``u_i`` lies in a box around ``P_i``.

    ``min X^T H X`` subject to ``A X <= b`` (11.11), ``H = [int B_i^(r) B_j^(r)]``.
    ``boxes="axis"`` (11.10): ``|x(u_i) - x_i| <= h`` per coordinate (independent problems);
    ``boxes="frame"`` (11.12): ``|(f(u_i) - P_i) . t_i| <= h t_i.t_i`` and the same with ``n_i``
    (planar).  ``h = half_width`` (the notes use 0.5).  Returns the curve and the exact KKT
    certificate(s).

    The notes print ``h_ij = int B_i B_j`` (and a sign-less constraint matrix); the fairness
    energy is the derivative energy (``derivative = 2`` by default); with ``derivative = 0``
    the printed matrix is used.
    """
    P = _points(points)
    ts = [to_rational(t) for t in params]
    if len(ts) != P.shape[0]:
        raise DimensionError("one parameter per point")
    h = to_rational(half_width, where="half_width")
    H = gram_matrix(knots, degree, derivative)
    N = collocation_matrix(ts, knots, degree)
    n, d, M = H.shape[0], P.shape[1], P.shape[0]
    if boxes == "axis":
        coords, certs = [], []
        for k in range(d):
            A = [row for row in N] + [[-x for x in row] for row in N]
            b = [P[i][k] + h for i in range(M)] + [-(P[i][k] - h) for i in range(M)]
            res = _qp.solve_qp(H.tolist(), [mpq(0)] * n, A, b)
            coords.append(res["x"])
            certs.append(res)
        T = np.array([[coords[k][j] for k in range(d)] for j in range(n)], dtype=object)
        return BSplineCurve(T, knots), {"per_coordinate": certs}
    if boxes == "frame":
        tans, norms = frame_boxes(P)
        Hbig = np.empty((2 * n, 2 * n), dtype=object)
        Hbig[...] = mpq(0)
        Hbig[:n, :n] = H
        Hbig[n:, n:] = H
        A, b = [], []
        for vecs in (tans, norms):
            for sign in (1, -1):
                for i in range(M):
                    v = vecs[i]
                    A.append([sign * N[i][j] * v[0] for j in range(n)] + [sign * N[i][j] * v[1] for j in range(n)])
                    pv = P[i][0] * v[0] + P[i][1] * v[1]
                    b.append(sign * pv + h * (v[0] ** 2 + v[1] ** 2))
        res = _qp.solve_qp(Hbig.tolist(), [mpq(0)] * (2 * n), A, b)
        x = res["x"]
        T = np.array([[x[j], x[n + j]] for j in range(n)], dtype=object)
        return BSplineCurve(T, knots), res
    raise InputError(f"boxes must be 'axis' or 'frame', got {boxes!r}")


def lsq_error(curve: BSplineCurve, points, params):
    """``Lsq = sum_i |P_i - f(t_i)|^2`` (11.1), exact."""
    P = _points(points)
    total = mpq(0)
    for p, t in zip(P, params):
        q = curve.evaluate(t)
        total += sum(((a - b) ** 2 for a, b in zip(p, q)), mpq(0))
    return total
