"""Real roots of polynomials in Bernstein form on [0, 1], in float64 with certified enclosures.

Sources: Sederberg's notes (003), chapter 9:

* 9.1 *convex hull marching* (:func:`marching_roots`): march from the left, each step
  to where the convex hull of the explicit Bézier curve ``(i/n, y_i)`` first meets the
  t-axis, subdivide there (de Casteljau), stop when the steps stall, deflate the root
  with (9.1) ``y^1_i = n/(i+1) y_{i+1}`` and go on;
* 9.2 *combined subdivide & derivative* (:func:`isolating_roots`): isolate by sign
  variations of the Bernstein coefficients (halving at .5, .25, .125), and when that
  does not isolate, split at the roots of the derivative; refine isolated roots with
  the modified regula falsi on Horner's rule in Bernstein form (O(n) per step);
* 9.3 products of Bernstein polynomials: :func:`exactcagd.exact.bernstein.product`;
* 9.4 *line ∩ rational Bézier curve* (:func:`line_roots`): ``f_i = w_i (a x_i + b y_i + c)``.

Certification (:func:`certify_roots`): the float methods only *propose* roots.  The
exact coefficients are enclosed in outward-rounded float intervals
(:mod:`exactcagd.numeric.enclose`); around each proposal a small interval is proven to
hold exactly one simple root (its restricted interval Bernstein coefficients have
exactly one sign variation and no zero), and every gap between the enclosures is
proven root-free (restricted coefficients of one strict sign), bisecting a gap when
needed.  What cannot be decided (multiple roots, clusters closer than the float
resolution, near-roots of complex pairs) stays as an *uncertified* enclosure.  So:

* every real root of the exact polynomial in [0, 1] lies in some returned enclosure
  (always, proven);
* an enclosure with ``certified=True`` holds exactly one root, of the stated
  multiplicity (simple, or an exact endpoint root);
* ``exists=True`` means at least one root is proven inside (a sign change).

Exact endpoint roots (``c_0 = 0`` or ``c_n = 0``) are found exactly and deflated with
(9.1) before any float work.  The exact reference routes are
:func:`exactcagd.exact.algebraic.real_roots_bernstein` and
:func:`exactcagd.numeric.descartes.isolate_exact`; ``method="exact"`` reads the roots off
flint's certified root balls of the factored integer polynomial (:func:`_exact_roots`).

>>> [round(r.t, 12) for r in bernstein_roots([1, -3, 1])]   # 8t^2 - 8t + 1
[0.146446609407, 0.853553390593]
>>> all(r.certified for r in bernstein_roots([1, -3, 1], method="marching"))
True
"""

from __future__ import annotations

import heapq
import math
from dataclasses import dataclass

import flint
import numpy as np
from gmpy2 import mpq

from ..errors import DimensionError, InputError, LimitError
from ..exact.algebraic import bernstein_integer_poly, exact_dyadic, real_roots, sign_at
from ..exact.bernstein import as_coefficients, derivative
from ..exact.scalars import to_rational, to_tolerance
from ..geometry._validate import instance_of
from ..geometry.bezier_curve import BezierCurve
from . import enclose as iv
from .descartes import isolate_in_unit_interval

__all__ = [
    "Root",
    "bernstein_roots",
    "marching_roots",
    "isolating_roots",
    "certify_roots",
    "deflate_left",
    "deflate_right",
    "line_roots",
    "METHODS",
]

METHODS = ("marching", "isolate", "exact")
U = iv.U


@dataclass(frozen=True)
class Root:
    """A root of a Bernstein polynomial on [0, 1] with a certified enclosure.

    Attributes
    ----------
    t : float
        Float estimate of the root (from the float method; the enclosure midpoint
        when the enclosure came from the certification alone; with ``method="exact"``
        the root correctly rounded, proven by exact or certain ball comparisons).
    interval : (float, float)
        ``lo <= hi``; proven to contain the roots it stands for.
    multiplicity : int
        Exact when ``certified``; otherwise the number of float roots merged here
        (an estimate, 0 when the float method saw nothing there).
    certified : bool
        Exactly one distinct root, of this multiplicity, lies in ``interval``.
    exists : bool
        At least one root lies in ``interval`` (proven).
    """

    t: float
    interval: tuple[float, float]
    multiplicity: int
    certified: bool
    exists: bool

    @property
    def width(self) -> float:
        return self.interval[1] - self.interval[0]

    def contains(self, x) -> bool:
        """True when the exact number ``x`` (rational or RealAlgebraic) lies in the enclosure."""
        lo, hi = self.interval
        return bool(mpq(lo) <= x) and bool(x <= mpq(hi))


# ---------------------------------------------------------------- deflation (9.1)
def deflate_left(y):
    """Divide out a root at t = 0 (notes 9.1, (9.1)): ``f = t f^1``, ``f^1_i = n/(i+1) y_{i+1}``.

    Exact for exact arrays (``y_0`` must be 0, it is ignored); works on floats too.

    >>> [str(x) for x in deflate_left(as_coefficients([0, 1, 1]))]   # 2t(1-t) + t^2 = t (2 - t)
    ['2', '1']
    """
    n = len(y) - 1
    if n == 0:
        raise InputError("cannot deflate a constant")
    scale = np.array([mpq(n, i + 1) if _is_exact(y) else n / (i + 1) for i in range(n)], dtype=object if _is_exact(y) else float)
    return np.asarray(y)[1:] * scale


def deflate_right(y):
    """Divide out a root at t = 1: ``f = (1 - t) f^1``, ``f^1_i = n/(n-i) y_i`` (mirror of (9.1))."""
    n = len(y) - 1
    if n == 0:
        raise InputError("cannot deflate a constant")
    scale = np.array([mpq(n, n - i) if _is_exact(y) else n / (n - i) for i in range(n)], dtype=object if _is_exact(y) else float)
    return np.asarray(y)[:-1] * scale


def _is_exact(y) -> bool:
    return isinstance(y, np.ndarray) and y.dtype == object


# ---------------------------------------------------------------- float helpers
def _split(y: np.ndarray, t: float):
    """Float de Casteljau subdivision at t (notes 2.3): pieces on [0, t] and [t, 1]."""
    n = len(y) - 1
    left, right = np.empty(n + 1), np.empty(n + 1)
    level = y
    left[0], right[n] = y[0], y[n]
    s = 1.0 - t
    for r in range(1, n + 1):
        level = s * level[:-1] + t * level[1:]
        left[r], right[n - r] = level[0], level[-1]
    return left, right


def _horner(y: np.ndarray, t: float) -> tuple[float, float]:
    """Value and running error bound at t of a float Bernstein polynomial (notes 3.2)."""
    value, bound = iv.horner_bound(y.reshape(-1, 1), np.zeros((len(y), 1)), t)
    return float(value[0]), float(bound[0])


def _noise(y: np.ndarray) -> float:
    return 4.0 * (len(y) + 1) * U * float(np.max(np.abs(y)))


# ---------------------------------------------------------------- 9.1 convex hull marching
#: hull steps per coefficient and per ``max_steps`` before marching gives up (LimitError)
_MARCH_WORK = 1


def marching_roots(y, tol: float = 1e-12, max_steps: int = 200) -> list[tuple[float, int]]:
    """Roots in [0, 1] of a float Bernstein polynomial by convex hull marching (notes 9.1).

    Each step goes to the left-most point where the convex hull of the explicit
    Bézier curve ``(i/n, y_i)`` can meet the t-axis: the smallest intercept of the
    chords from ``(0, y_0)`` to all points ``(i/n, y_i)`` closer to the axis (the chord
    rule of notes 7.7.8 — never right of the true hull crossing, so no root is
    skipped; chords to the points across the axis only could overshoot).  The piece
    right of the step is kept (de Casteljau).  Steps shorter than ``tol`` end the
    march at a root, which is deflated with (9.1); a sign change of ``f(t_i)`` between
    steps (rounding "sneaking past" a root) also ends it.

    One addition to the printed algorithm: once the piece's coefficients show exactly
    one sign change (the next root is isolated), the march also proceeds from the right
    end of a copy of the piece (the two-sided hull clip of Bézier clipping, 7.7), which
    turns the linear convergence of the one-sided march into the fast convergence of
    clipping; the root is then split off the piece and deflated as printed.

    Returns
    -------
    list of (t, multiplicity) with multiplicity 1 each (repeated roots repeat), sorted.

    Raises
    ------
    LimitError
        After ``max_steps * (n + 1)`` hull steps in all (clustered roots can make
        the march restart without end); :func:`bernstein_roots` then answers exactly.
    """
    orig = np.asarray(y, dtype=float).copy()
    y = orig.copy()
    stall = 24
    work = _MARCH_WORK * max_steps * len(orig)  # hull steps in all, over every restart
    roots: list[float] = []
    left = 0.0  # the current piece is f on [left, 1], deflated ``here`` times at ``left``
    here = 0
    steps = 0
    err = U * float(np.max(np.abs(y)))  # running bound on the error of the piece's coefficients

    def restart(root: float, mult: int = 1):
        # the piece right of a root, split off the *original* polynomial (no error build-up)
        # and deflated once per root found at this place (notes (9.1))
        nonlocal y, left, here, steps, err
        here = here + mult if (roots and root == left) else mult
        roots.extend([root] * mult)
        left = root
        if root >= 1.0:
            y = orig[:1]
            return
        _, piece = _split(orig, root)
        err = (2 * len(orig) + 1) * U * float(np.max(np.abs(orig)))
        for _ in range(min(here, len(piece) - 1)):
            piece[0] = 0.0
            piece = deflate_left(piece)
            err *= len(piece)
        y = piece
        steps = 0

    while len(y) > 1:
        work -= 1
        if work < 0:
            # clustered roots (prod (t - i/64)) kept the march restarting without end
            raise LimitError(f"convex hull marching exceeded its work bound ({_MARCH_WORK * max_steps * len(orig)} steps)")
        n = len(y) - 1
        noise = err + _noise(y)
        if np.all(np.abs(y) <= noise):
            # the whole piece is rounding noise (e.g. the sliver [root, 1] left after a
            # root within ~1e-12 of 1): nothing more can be decided, and taking y_0 ~ 0
            # for another root would double the last one (certify_roots covers the rest);
            # a march that *arrived* here (no root taken at ``left`` yet) converged to one
            if here == 0 and steps > 0:
                roots.append(left)
            break
        if abs(y[0]) <= noise:
            restart(left)
            continue
        s0 = 1.0 if y[0] > 0 else -1.0
        opposite = np.nonzero(s0 * y[1:] <= 0)[0] + 1
        if opposite.size == 0:
            break  # the hull never reaches the axis: no more roots
        width = 1.0 - left
        if _variations(y, noise) == 1 and abs(y[-1]) > noise:
            restart(left + _window_root(y, tol / width, max_steps) * width)
            continue
        down_chords = np.nonzero(s0 * y[1:] < s0 * y[0])[0] + 1
        ts = (down_chords / n) * (y[0] / (y[0] - y[down_chords]))
        step = float(np.min(ts))
        steps += 1
        if steps == stall and n >= 2:
            # creeping towards a multiple root (or a near miss): march on the derivative
            # to its left-most root c (the idea of notes 9.2); f is monotone on [left, c]
            action = _stall(y, tol / width, max_steps, err)
            if action is not None:
                kind, c, mult = action
                if kind == "root":
                    restart(left + c * width, mult)
                else:  # jump: no root before c
                    _, y = _split(y, c)
                    err += 2 * n * U * float(np.max(np.abs(y)))
                    left, here, steps = left + c * width, 0, 0
                continue
        _, right = _split(y, step)
        err += 2 * n * U * float(np.max(np.abs(y)))
        if step * width <= tol or steps >= max_steps:
            restart(left + step * width)
            continue
        if right[0] * s0 < 0:
            # rounding sneaked past a root (or the step is the root, e.g. step = 1 for a
            # root within rounding of the right end): it lies in [left, left + step]
            window, _ = _split(y, step)
            restart(left + _window_root(window, tol / max(step * width, 2.0**-1074), max_steps) * step * width)
            continue
        y = right
        left = left + step * width
        here = 0
    return _count(roots)


def _stall(y: np.ndarray, tol: float, max_steps: int, err: float):
    """Left-most critical point c of the piece and what it means (see :func:`marching_roots`)."""
    n = len(y) - 1
    # the derivative's roots by subdivide & derivative (9.2), not by marching: a march that
    # stalls on the derivative would recurse on the second derivative, and so on — with
    # clustered roots (Wilkinson-like, degree >= 15) that cascade never finished
    crit = isolating_roots(n * (y[1:] - y[:-1]), tol, _err=2 * n * (err + _noise(y)))
    crit = [(t, m) for t, m in crit if 0.0 < t < 1.0]
    if not crit:
        return None
    c, m = crit[0]
    value, herr = _horner(y, c)
    if abs(value) <= herr + err + _noise(y):
        return "root", c, m + 1
    if (value > 0) == (y[0] > 0):
        return "jump", c, 0
    left, _ = _split(y, c)
    return "root", _window_root(left, tol / c, max_steps) * c, 1


def _window_root(y: np.ndarray, tol: float, max_steps: int) -> float:
    """The one root of a piece with one sign change: march from both ends (local parameter)."""
    a_glob, b_glob = 0.0, 1.0
    w = y.copy()
    n = len(w) - 1
    for _ in range(max_steps):
        if b_glob - a_glob <= tol:
            break
        s0 = 1.0 if w[0] > 0 else -1.0
        sn = 1.0 if w[-1] > 0 else -1.0
        if w[0] == 0 or w[-1] == 0 or s0 == sn:
            break
        opp = np.nonzero(s0 * w[1:] < s0 * w[0])[0] + 1
        opp_r = np.nonzero(sn * w[:-1] < sn * w[-1])[0]
        a = float(np.min((opp / n) * (w[0] / (w[0] - w[opp]))))
        b = 1.0 - float(np.min(((n - opp_r) / n) * (w[-1] / (w[-1] - w[opp_r]))))
        if b < a:
            # exactly a <= root <= b; crossed clips are rounding (e.g. a linear piece, where
            # both clips are the root itself): the root is pinned between them
            a, b = b, a
            width = b_glob - a_glob
            a_glob, b_glob = a_glob + max(a, 0.0) * width, a_glob + min(b, 1.0) * width
            break
        if not (0.0 <= a and b <= 1.0):
            break
        if b - a > 0.7:  # little progress: halve instead, keeping the sign change
            a, b = (0.0, 0.5) if (_split(w, 0.5)[0][-1] > 0) != (w[0] > 0) else (0.5, 1.0)
        width = b_glob - a_glob
        if b < 1.0:
            w, _ = _split(w, b)
        if a > 0.0:
            _, w = _split(w, a / b)
        a_glob, b_glob = a_glob + a * width, a_glob + b * width
    return 0.5 * (a_glob + b_glob)


def _count(roots: list[float], merge: float = 0.0) -> list[tuple[float, int]]:
    out: list[tuple[float, int]] = []
    for r in sorted(roots):
        if out and abs(r - out[-1][0]) <= merge:
            t, m = out[-1]
            out[-1] = ((t * m + r) / (m + 1), m + 1)
        else:
            out.append((r, 1))
    return out


# ---------------------------------------------------------------- 9.2 subdivide & derivative
def _variations(y: np.ndarray, noise: float) -> int:
    signs = np.sign(np.where(np.abs(y) <= noise, 0.0, y))
    signs = signs[signs != 0]
    return int(np.count_nonzero(signs[1:] != signs[:-1]))


def _regula_falsi(y: np.ndarray, a: float, b: float, fa: float, fb: float, tol_local: float) -> float:
    """Modified (Illinois) regula falsi on [a, b] of the local piece, Horner evaluation."""
    side = 0
    for _ in range(200):
        x = (a * fb - b * fa) / (fb - fa)
        if not (a < x < b):
            x = 0.5 * (a + b)
        fx, err = _horner(y, x)
        if abs(fx) <= err or b - a <= tol_local:
            return x
        if (fx > 0) == (fa > 0):
            a, fa = x, fx
            if side == -1:
                fb *= 0.5
            side = -1
        else:
            b, fb = x, fx
            if side == 1:
                fa *= 0.5
            side = 1
    return 0.5 * (a + b)


def isolating_roots(y, tol: float = 1e-12, _err: float | None = None) -> list[tuple[float, int]]:
    """Roots in [0, 1] by the combined subdivide & derivative algorithm (notes 9.2).

    Isolation: exactly one sign change of the Bernstein coefficients isolates a root
    (variation diminishing).  A piece with more changes is halved (at .5, then .25,
    .125 of the original, i.e. up to three halvings); if still not isolated, the roots
    of its derivative (found by the same algorithm, one degree lower) split it into
    monotone pieces, each holding at most one root.  A derivative root where the
    value is below the running error bound is reported as a multiple root.
    Isolated roots are refined by the modified regula falsi with Horner's rule.

    Returns
    -------
    list of (t, multiplicity), sorted (multiplicity > 1 only for detected multiple roots).
    """
    y = np.asarray(y, dtype=float)
    out: list[tuple[float, int]] = []
    err = U * float(np.max(np.abs(y))) if _err is None else _err
    _isolate(y, 0.0, 1.0, 0, tol, out, err)
    _end_roots(y, err, tol, out)
    out.sort()
    return out


def _end_roots(y: np.ndarray, err: float, tol: float, out: list) -> None:
    """Propose t = 0 / t = 1 where the end coefficient is rounding noise.

    Sign variations ignore coefficients below the noise level, so a root within about
    ``1e-15`` of an end of [0, 1] (``y_0`` or ``y_n`` tiny but not 0) shows no variation
    and would not be proposed at all; the end itself is then the best float estimate
    (:func:`certify_roots` proves or encloses the root next to it).  A root already
    found within ``2^-20`` of that end explains the small coefficient; a second estimate
    next to it would only keep the certification from separating the two.
    """
    if len(y) < 2:
        return
    noise = err + _noise(y)
    near = max(tol, 2.0**-20)
    for t, value in ((0.0, y[0]), (1.0, y[-1])):
        if abs(value) <= noise and not any(abs(r - t) <= near for r, _ in out):
            out.append((t, 1))


def _isolate(y: np.ndarray, a: float, b: float, depth: int, tol: float, out: list, err: float) -> None:
    """``err`` bounds the error of the piece's coefficients (grows with each float split)."""
    n = len(y) - 1
    if n == 0:
        return
    noise = err + _noise(y)
    v = _variations(y, noise)
    if v == 0:
        return
    width = b - a
    if v == 1 and abs(y[0]) > noise and abs(y[-1]) > noise:
        x = _regula_falsi(y, 0.0, 1.0, float(y[0]), float(y[-1]), tol / width)
        out.append((a + x * width, 1))
        return
    if depth < 3:
        for m in (0.5, 0.4375, 0.5625):  # avoid splitting exactly on a root
            value, herr = _horner(y, m)
            if abs(value) > herr + err:
                break
        left, right = _split(y, m)
        err = err + 2 * n * U * float(np.max(np.abs(y)))
        mid = a + m * width
        _isolate(left, a, mid, depth + 1, tol, out, err)
        _isolate(right, mid, b, depth + 1, tol, out, err)
        return
    _by_derivative(y, a, b, tol, out, err)


def _by_derivative(y: np.ndarray, a: float, b: float, tol: float, out: list, err: float) -> None:
    """Split at the derivative's roots: between them f is monotone (notes 9.2, Fig. 9.3.h)."""
    n = len(y) - 1
    width = b - a
    crit = isolating_roots(n * (y[1:] - y[:-1]), tol / width, _err=2 * n * err)
    points = [(0.0, 0)] + [(t, m) for t, m in crit if 0.0 < t < 1.0] + [(1.0, 0)]
    values = []
    for t, m in points:
        value, herr = _horner(y, t)
        values.append(0.0 if abs(value) <= herr + err else value)
    for k, (t, m) in enumerate(points):
        if values[k] == 0.0 and 0 < k < len(points) - 1:
            out.append((a + t * width, m + 1))
        elif values[k] == 0.0 and (a + t * width in (0.0, 1.0) or k == 0):
            out.append((a + t * width, 1))
    for k in range(len(points) - 1):
        fa, fb = values[k], values[k + 1]
        if fa * fb < 0:
            x = _regula_falsi(y, points[k][0], points[k + 1][0], fa, fb, tol / width)
            out.append((a + x * width, 1))


# ---------------------------------------------------------------- certification
def _validated(coeffs) -> np.ndarray:
    """Exact 1-D coefficient array of a nonzero polynomial (errors name the argument)."""
    c = coeffs if (isinstance(coeffs, np.ndarray) and coeffs.dtype == object) else as_coefficients(coeffs)
    if c.ndim != 1:
        raise DimensionError("a Bernstein polynomial needs a 1-D coefficient sequence")
    if all(x == 0 for x in c):
        raise InputError("the zero polynomial has every number as a root")
    return c


def _prepare(coeffs) -> tuple[np.ndarray, list[Root], np.ndarray]:
    """Exact coefficients: endpoint roots found exactly and deflated; scaled by 2^k."""
    c = _validated(coeffs)
    ends: list[Root] = []
    k0 = 0
    while c[0] == 0:
        c = deflate_left(c)
        k0 += 1
    k1 = 0
    while c[-1] == 0:
        c = deflate_right(c)
        k1 += 1
    if k0:
        ends.append(Root(0.0, (0.0, 0.0), k0, True, True))
    if k1:
        ends.append(Root(1.0, (1.0, 1.0), k1, True, True))
    k = iv.power2_scale(c)
    c = c * (mpq(2) ** k)
    return c, ends, np.array([float(x) for x in c])


def _restricted(lo, hi, a: float, b: float):
    return iv.restrict(lo, hi, a, b)


def _sign_pattern(lo: np.ndarray, hi: np.ndarray) -> tuple[bool, int]:
    """(no coefficient interval contains 0, number of sign variations)."""
    if not (np.all(np.isfinite(lo)) and np.all(np.isfinite(hi))):
        return False, -1
    definite = bool(np.all((lo > 0) | (hi < 0)))
    if not definite:
        return False, -1
    signs = np.where(lo > 0, 1, -1)
    return True, int(np.count_nonzero(signs[1:] != signs[:-1]))


def _prove_simple(lo, hi, dlo, dhi, r: float, limit: float):
    """Smallest tried interval around r with exactly one simple root, ``"none"`` if one is
    proven root-free, else None.

    Exactly one simple root in [a, b]: the restricted coefficients have no zero and one
    sign variation (Descartes), or the end values have opposite signs and the
    derivative's restricted coefficients one strict sign (monotone).
    """
    rho = max(abs(r), 1.0) * 2.0**-50
    while rho <= limit:
        a, b = max(0.0, iv.down(r - rho)), min(1.0, iv.up(r + 1.5 * rho))
        rlo, rhi = _restricted(lo, hi, a, b)
        definite, v = _sign_pattern(rlo, rhi)
        if definite and v == 1:
            return a, b
        ends_definite, ve = _sign_pattern(np.array([rlo[0], rlo[-1]]), np.array([rhi[0], rhi[-1]]))
        if ends_definite and ve == 1 and dlo.size:
            d_definite, dv = _sign_pattern(*_restricted(dlo, dhi, a, b))
            if d_definite and dv == 0:
                return a, b
        rho *= 16.0
    if _root_free(lo, hi, max(0.0, r - limit), min(1.0, r + limit)):
        return "none"
    return None


def _cluster_radius(lo, hi, t: float, limit: float) -> float:
    """Radius of an enclosure around an unresolved cluster at t: grow by 4 until the two
    shells [t + rho, t + 2 rho] and [t - 2 rho, t - rho] are proven root-free (the region
    where float data cannot decide is then inside)."""
    rho = max(abs(t), 1.0) * 2.0**-40
    while rho < limit:
        right = t + rho >= 1.0 or _root_free(lo, hi, t + rho, min(1.0, t + 2 * rho))
        left = t - rho <= 0.0 or _root_free(lo, hi, max(0.0, t - 2 * rho), t - rho)
        if right and left:
            return rho
        rho *= 4.0
    return rho


def _root_free(lo, hi, a: float, b: float) -> bool:
    definite, v = _sign_pattern(*_restricted(lo, hi, a, b))
    return definite and v == 0


def _exists(lo, hi, a: float, b: float) -> bool:
    rlo, rhi = _restricted(lo, hi, a, b)
    first = (rlo[0] > 0, rhi[0] < 0)
    last = (rlo[-1] > 0, rhi[-1] < 0)
    return bool((first[0] and last[1]) or (first[1] and last[0]))


def certify_roots(coeffs, estimates, tol: float = 1e-12) -> list[Root]:
    """Turn float root estimates into certified enclosures of the exact roots.

    Parameters
    ----------
    coeffs : exact Bernstein coefficients (the polynomial whose roots are meant)
    estimates : list of (t, multiplicity) from a float method (may be wrong or incomplete)
    tol : smallest width down to which a gap is bisected before it is given up

    Returns
    -------
    list of Root, sorted and disjoint; their union holds every root in [0, 1].
    """
    c, ends, _ = _prepare(coeffs)
    lo, hi = iv.enclose(c)
    dlo, dhi = iv.enclose(derivative(c)) if len(c) > 1 else (np.zeros(0), np.zeros(0))
    boxes: list[list] = []  # [a, b, t_estimate, multiplicity, certified]
    if len(c) > 1:
        ests = sorted((float(t), int(m)) for t, m in estimates if 0.0 <= t <= 1.0)
        for i, (t, m) in enumerate(ests):
            gap_l = t - ests[i - 1][0] if i > 0 else 1.0
            gap_r = ests[i + 1][0] - t if i + 1 < len(ests) else 1.0
            limit = min(gap_l, gap_r, 1.0) / 4.0
            proven = _prove_simple(lo, hi, dlo, dhi, t, limit) if m == 1 else None
            if proven == "none":
                continue  # proven root-free around a spurious float root
            if proven is not None:
                boxes.append([proven[0], proven[1], t, 1, True])
            else:
                rho = _cluster_radius(lo, hi, t, max(limit, 2.0**-30))
                boxes.append([max(0.0, t - rho), min(1.0, t + rho), t, m, False])
        boxes = _merge(boxes)
        boxes = _fill_gaps(lo, hi, boxes, max(tol, 2.0**-46))
    roots = []
    for a, b, t, m, cert in boxes:
        if cert:
            roots.append(Root(float(t), (float(a), float(b)), 1, True, True))
        else:
            t_est = t if t is not None else 0.5 * (a + b)
            roots.append(Root(float(t_est), (float(a), float(b)), m, False, _exists(lo, hi, a, b)))
    # exact endpoint roots: shrink neighbouring enclosures away from 0 and 1 is not needed;
    # they are disjoint because the deflated polynomial is non-zero at 0 and 1 — but an
    # enclosure of the deflated polynomial may still touch 0 or 1, so keep both.
    return sorted(ends + roots, key=lambda r: (r.interval[0], r.interval[1]))


def _merge(boxes: list[list]) -> list[list]:
    boxes.sort(key=lambda b: b[0])
    out: list[list] = []
    for box in boxes:
        if out and box[0] <= out[-1][1]:
            prev = out[-1]
            m = prev[3] + box[3]
            t = None if prev[2] is None or box[2] is None else (prev[2] * prev[3] + box[2] * box[3]) / max(m, 1)
            out[-1] = [prev[0], max(prev[1], box[1]), t, m, False]
        else:
            out.append(list(box))
    return out


def _fill_gaps(lo, hi, boxes: list[list], min_width: float, budget: int = 1000) -> list[list]:
    """Prove every gap root-free; what cannot be proven joins a neighbour or becomes a box.

    A gap that cannot be proven is bisected, down to ``max(min_width, len * 2**-24)``
    (so the region around a cluster, where nothing can be proven in float, costs a
    bounded number of tests), and at most ``budget`` tests are spent in all.
    """
    edges = [0.0] + [x for b in boxes for x in (b[0], b[1])] + [1.0]
    gaps = [(edges[2 * i], edges[2 * i + 1]) for i in range(len(boxes) + 1)]
    unproven: list[tuple[float, float]] = []
    # widest pieces first (a heap): near an unresolved multiple root the pieces that
    # cannot be proven multiply, and a depth-first order would spend the whole budget
    # there and leave wide, easily proven pieces (and the roots beyond) merged into it
    heap = [(-(b - a), a, b, max(min_width, (b - a) * 2.0**-24)) for a, b in gaps if b > a]
    heapq.heapify(heap)
    while heap:
        _, x, y, floor = heapq.heappop(heap)
        if budget <= 0:
            unproven.append((x, y))
            continue
        budget -= 1
        if _root_free(lo, hi, x, y):
            continue
        if y - x <= floor:
            unproven.append((x, y))
            continue
        m = 0.5 * (x + y)
        heapq.heappush(heap, (-(m - x), x, m, floor))
        heapq.heappush(heap, (-(y - m), m, y, floor))
    if not unproven:
        return boxes
    for x, y in unproven:
        boxes.append([x, y, None, 0, False])
    return _merge_touching(boxes)


def _merge_touching(boxes: list[list]) -> list[list]:
    """Merge touching boxes, and uncertified ones closer than their width (the hull of
    the unproven fragments around one multiple root is one enclosure)."""
    boxes.sort(key=lambda b: b[0])
    out: list[list] = []
    for box in boxes:
        near = out and not box[4] and not out[-1][4] and box[0] - out[-1][1] <= max(box[1] - box[0], out[-1][1] - out[-1][0])
        if out and (box[0] <= out[-1][1] or near):
            prev = out[-1]
            m = prev[3] + box[3]
            ts = [(p[2], p[3]) for p in (prev, box) if p[2] is not None and p[3] > 0]
            t = sum(tt * mm for tt, mm in ts) / sum(mm for _, mm in ts) if ts else None
            cert = False
            out[-1] = [prev[0], max(prev[1], box[1]), t, m, cert]
        else:
            out.append(list(box))
    return out


# ---------------------------------------------------------------- public entry
def bernstein_roots(coeffs, method: str = "isolate", tol: float = 1e-12, certify: bool = True) -> list[Root]:
    """Real roots in [0, 1] of a polynomial in Bernstein form, with certified enclosures.

    Parameters
    ----------
    coeffs : sequence of exact numbers (ints, ``"p/q"`` strings, Fractions, floats = their binary value)
        Bernstein coefficients on [0, 1].
    method : "isolate" (notes 9.2, default), "marching" (notes 9.1) or "exact"
        ``"exact"`` factors the exact polynomial over the integers (flint): rational roots
        come exactly from linear factors, the others from Arb's certified root balls, with
        exact isolation and bisection as the fallback.  Each root comes in the smallest
        float interval that holds it (one float step, or one float) with ``t`` the root
        correctly rounded, certified with its exact multiplicity, clusters and multiple
        roots included; only roots within one float step of each other, which no float
        interval separates, share one enclosure (``certified=False``, ``exists=True``, the
        sum of their multiplicities).  On exact input it is faster than the float methods
        (``benchmarks/results/bench_roots_intersection.md``).
    tol : float
        Parameter tolerance (``"exact"`` ignores it: its enclosures are one float step
        wide, narrower than any ``tol``).
    certify : bool
        With False, the raw float roots come back (``interval = (t, t)``, nothing
        proven); used to time the float methods alone.

    Returns
    -------
    list of Root (see :class:`Root` and :func:`certify_roots` for the guarantees).

    Examples
    --------
    >>> r = bernstein_roots([-1, 0, 1])          # 2t - 1
    >>> r[0].certified, r[0].interval[0] <= 0.5 <= r[0].interval[1]
    (True, True)
    >>> s = bernstein_roots([1, -3, 1], method="exact")   # (2 -+ sqrt 2) / 4, correctly rounded
    >>> [x.t for x in s], [math.nextafter(x.interval[0], 1.0) == x.interval[1] for x in s]
    ([0.14644660940672624, 0.8535533905932737], [True, True])
    """
    if method not in METHODS:
        raise InputError(f"unknown root-finding method {method!r}; expected one of {METHODS}")
    tol = to_tolerance(tol)
    if method == "exact":
        return _exact_roots(_validated(coeffs))
    c, ends, y = _prepare(coeffs)
    if len(c) <= 1:
        return ends
    finder = marching_roots if method == "marching" else isolating_roots
    try:
        estimates = finder(y, tol)
    except LimitError:
        # the float method hit its work bound: the exact route answers (certified)
        return _exact_roots(_validated(coeffs))
    if not certify:
        raw = [Root(t, (t, t), m, False, False) for t, m in estimates]
        return sorted(ends + raw, key=lambda r: r.t)
    full = coeffs if (isinstance(coeffs, np.ndarray) and coeffs.dtype == object) else as_coefficients(coeffs)
    return certify_roots(full, estimates, tol)


def _exact_roots(c: np.ndarray) -> list[Root]:
    """Roots in [0, 1] of exact Bernstein coefficients ``c``, each in the smallest float
    interval that holds it.

    Sources: Sederberg's notes (003) 3.3 for the power form; Arb's
    ``arb_fmpz_poly_complex_roots`` (F. Johansson) for the certified root balls.  The
    integer power form is factored over the integers; a linear factor gives its rational
    root exactly; the real roots of every other (irreducible) factor come from flint's
    root balls (:func:`_roots_in_balls`), or, for a factor with coefficients longer than
    :data:`LARGE_COEFFICIENT_BITS`, from exact isolation in [0, 1] by Descartes' rule
    (:func:`_roots_by_descartes`; flint isolates all complex roots, which takes minutes
    for some such factors).  When a ball cannot be decided at the
    precisions of ``BALL_PRECISIONS``, exact isolation and bisection
    (:func:`_roots_by_bisection`) answers instead.  Roots that no float interval can
    separate share one enclosure (:func:`_share_enclosures`).
    """
    poly = bernstein_integer_poly(c)
    if poly.degree() < 1:
        return []
    roots = _roots_from_factors(poly)
    return _share_enclosures(_roots_by_bisection(poly) if roots is None else roots)


#: irreducible factors with a coefficient longer than this (bits) are isolated in [0, 1] by
#: Descartes' rule on Bernstein coefficients (:func:`_roots_by_descartes`), not by flint's
#: balls of all their complex roots: measured on the quadratic with Bernstein coefficients
#: ``[c, -1, 1]`` (a complex pair within ~c^-1/2 of t = 1), ``complex_roots`` takes 2 ms for a
#: 300-bit ``c``, 94 ms at 700, 1.6 s at 1000 and over a minute at 2000 bits, where the
#: Descartes isolation takes under 1 ms at 20,000 bits
LARGE_COEFFICIENT_BITS = 256


def _roots_by_descartes(factor: flint.fmpz_poly, mult: int) -> list[Root]:
    """The roots in [0, 1] of a square-free integer polynomial by exact isolation in [0, 1]
    alone (:func:`exactcagd.numeric.descartes.isolate_in_unit_interval`: Descartes' rule of
    signs on Bernstein coefficients with bisection, notes 003 9.2 -- the
    Vincent-Collins-Akritas method), each interval then bisected exactly into one float step
    (:func:`_float_step`)."""
    roots = []
    for lo, hi in isolate_in_unit_interval(factor):
        t, a, b = _rational_step(lo) if lo == hi else _float_step(factor, lo, hi)
        roots.append(Root(t, (a, b), mult, True, True))
    return roots


def _float_step(poly: flint.fmpz_poly, lo: mpq, hi: mpq) -> tuple[float, float, float]:
    """``(t, a, b)`` for the only root of the square-free ``poly`` in the open interval
    ``(lo, hi)`` (nonzero at both ends): ``[a, b]`` is one float step, or one float when the
    root is that float, holding it (inside [0, 1] when ``(lo, hi)`` is: 0 and 1 are
    floats), and ``t`` the root correctly rounded (ties to even), decided by exact signs
    only.  ``(lo, hi)`` is halved until its ends round outward into one float step; a
    midpoint where ``poly`` vanishes is the root itself (rational)."""
    s_lo = sign_at(poly, lo)
    while True:
        a, b = iv.enclose_scalar(lo)[0], iv.enclose_scalar(hi)[1]
        if b <= math.nextafter(a, math.inf):
            break
        mid = (lo + hi) / 2
        s_mid = sign_at(poly, mid)
        if s_mid == 0:
            return _rational_step(mid)
        lo, hi = (mid, hi) if s_mid == s_lo else (lo, mid)
    midpoint = (mpq(a) + mpq(b)) / 2
    if lo < midpoint < hi:
        s_mid = sign_at(poly, midpoint)
        if s_mid == 0:
            return _rational_step(midpoint)
        below = s_mid != s_lo
    else:
        below = midpoint >= hi
    return (a if below else b), a, b


def _rational_step(q: mpq) -> tuple[float, float, float]:
    """:func:`_float_step` for a rational root ``q``: ``float(q)`` is correctly rounded."""
    return (float(q), *iv.enclose_scalar(q))


#: working precisions (bits) of flint's root balls, tried in turn for each irreducible factor
BALL_PRECISIONS = (64, 192)


def _roots_from_factors(poly: flint.fmpz_poly) -> list[Root] | None:
    """Roots in [0, 1] of a nonconstant integer polynomial, sorted, or None when undecided."""
    _, factors = poly.factor()
    roots = []
    for factor, mult in factors:
        if factor.degree() == 1:
            c0, c1 = factor.coeffs()
            q = mpq(-int(c0), int(c1))
            if 0 <= q <= 1:
                roots.append(Root(float(q), iv.enclose_scalar(q), int(mult), True, True))
            continue
        if max(abs(int(k)) for k in factor.coeffs()).bit_length() > LARGE_COEFFICIENT_BITS:
            roots.extend(_roots_by_descartes(factor, int(mult)))
            continue
        for prec in BALL_PRECISIONS:
            found = _roots_in_balls(factor, int(mult), prec)
            if found is not None:
                break
        else:
            return None
        roots.extend(found)
    return sorted(roots, key=lambda r: r.interval)


def _roots_in_balls(factor: flint.fmpz_poly, mult: int, prec: int) -> list[Root] | None:
    """The roots in (0, 1) of an irreducible integer polynomial of degree >= 2, from flint's
    root balls at ``prec`` bits, or None when a ball does not decide (:func:`_round_ball`).

    ``fmpz_poly.complex_roots`` (Arb's ``arb_fmpz_poly_complex_roots``) returns disjoint
    balls, each holding exactly one root, real roots with an imaginary part of exactly zero.
    A ball inside (0, 1) or wholly outside [0, 1] decides membership; one over 0 or 1 is
    decided by exact signs (:func:`_round_over_end`).
    """
    old = flint.ctx.prec
    flint.ctx.prec = prec
    try:
        out = []
        for ball, _ in factor.complex_roots():
            if not ball.imag.is_zero():
                continue
            real = ball.real
            if real < 0 or real > 1:
                continue
            rounded = _round_ball(real) if (real > 0 and real < 1) else _round_over_end(factor, real)
            if rounded is None:
                return None
            if rounded != "outside":
                x, lo, hi = rounded
                out.append(Root(x, (lo, hi), mult, True, True))
        return out
    finally:
        flint.ctx.prec = old


def _round_ball(real: flint.arb) -> tuple[float, float, float] | None:
    """``(x, lo, hi)``: every number in the ball rounds to the float ``x`` and lies in the
    float step ``[lo, hi]``, ``[x, next float]`` or ``[previous float, x]``; None when the
    ball reaches a rounding boundary (the midpoint of ``x`` and a float neighbour) or
    holds ``x`` inside.

    Needs ``flint.ctx.prec >= 54``, so that the midpoints of adjacent floats are exact;
    arb's comparisons are certain (true for every point of the ball).
    """
    x = float(real.mid())
    exact = flint.arb(x)
    if real >= x:
        above = math.nextafter(x, math.inf)
        return (x, x, above) if real < (exact + above) / 2 else None
    if real <= x:
        below = math.nextafter(x, -math.inf)
        return (x, below, x) if (exact + below) / 2 < real else None
    return None


def _round_over_end(factor: flint.fmpz_poly, real: flint.arb):
    """:func:`_round_ball` for a real root ball over 0 or 1, in exact rationals: ``"outside"``
    when the root is not in (0, 1), else ``(x, lo, hi)`` or None as there.

    The factor has no rational root, so it is nonzero at every rational point and changes
    sign exactly once in the ball: the root exceeds 0 iff the factor has the same sign at
    0 as at the ball's lower end (and likewise at 1 and the upper end).  The root then lies
    in the ball clipped to the open interval (0, 1).
    """
    mid, rad = exact_dyadic(real.mid()), exact_dyadic(real.rad())
    lo, hi = mid - rad, mid + rad
    if lo <= 0:
        if sign_at(factor, lo) != sign_at(factor, mpq(0)):
            return "outside"
        lo = mpq(0)
    if hi >= 1:
        if sign_at(factor, hi) != sign_at(factor, mpq(1)):
            return "outside"
        hi = mpq(1)
    x = float((lo + hi) / 2)  # gmpy2 rounds correctly
    exact = mpq(x)
    if lo >= exact:
        above = math.nextafter(x, math.inf)
        return (x, x, above) if hi < (exact + mpq(above)) / 2 else None
    if hi <= exact:
        below = math.nextafter(x, -math.inf)
        return (x, below, x) if (exact + mpq(below)) / 2 < lo else None
    return None


def _roots_by_bisection(poly: flint.fmpz_poly) -> list[Root]:
    """Roots in [0, 1] by exact isolation (:func:`exactcagd.exact.algebraic.real_roots`),
    each in its float step found by exact comparisons (the root refined by exact bisection
    as far as they need), ``t`` the root correctly rounded (compared with the step's
    midpoint)."""
    roots = []
    for r, m in real_roots(poly, 0, 1):
        if r.is_rational:
            roots.append(Root(float(r.value), iv.enclose_scalar(r.value), m, True, True))
            continue
        x = float(r)  # within one float step of r (RealAlgebraic.__float__)
        lo, hi = (x, math.nextafter(x, math.inf)) if r > x else (math.nextafter(x, -math.inf), x)
        t = lo if r < (mpq(lo) + mpq(hi)) / 2 else hi
        roots.append(Root(t, (max(lo, 0.0), min(hi, 1.0)), m, True, True))
    return sorted(roots, key=lambda r: r.interval)


def _share_enclosures(roots: list[Root]) -> list[Root]:
    """Roots whose smallest float enclosures hold each other (roots within one float step
    of each other) as one uncertified Root: the hull of their enclosures, the sum of their
    multiplicities, ``t`` of the one of highest multiplicity; ``roots`` sorted.

    With smallest enclosures, the root of ``b`` lies in ``a``'s enclosure exactly when
    ``b``'s enclosure lies inside ``a``'s.
    """
    groups: list[list[Root]] = []
    for root in roots:
        if groups and any(_within(root.interval, o.interval) or _within(o.interval, root.interval) for o in groups[-1]):
            groups[-1].append(root)
        else:
            groups.append([root])
    out = []
    for group in groups:
        if len(group) == 1:
            out.append(group[0])
            continue
        lead = max(group, key=lambda r: r.multiplicity)
        hull = (min(r.interval[0] for r in group), max(r.interval[1] for r in group))
        out.append(Root(lead.t, hull, sum(r.multiplicity for r in group), False, True))
    return out


def _within(inner: tuple[float, float], outer: tuple[float, float]) -> bool:
    return outer[0] <= inner[0] and inner[1] <= outer[1]


# ---------------------------------------------------------------- 9.4 line ∩ rational curve
def line_coefficients(curve, line) -> np.ndarray:
    """Exact Bernstein coefficients ``f_i = w_i (a x_i + b y_i + c)`` (notes 9.4).

    ``line = (a, b, c)`` is the line ``a x + b y + c = 0`` (homogeneously ``aX + bY + cW``).
    """
    instance_of(curve, BezierCurve, "curve")
    if curve.dimension != 2:
        raise DimensionError(f"line_roots needs a planar curve, got dimension {curve.dimension}")
    if not isinstance(line, (tuple, list, np.ndarray)) or len(line) != 3:
        raise InputError("line: a line is given as (a, b, c) for a x + b y + c = 0")
    a, b, c = (to_rational(v, where="line coefficient") for v in line)
    if a == 0 and b == 0:
        raise InputError("(0, 0, c) is not a line")
    hom = curve.homogeneous()
    return np.array([a * h[0] + b * h[1] + c * h[2] for h in hom], dtype=object)


def line_roots(curve, line, method: str = "isolate", tol: float = 1e-12) -> list[Root]:
    """Parameters where a (rational) planar Bézier curve meets a line (notes 9.4).

    >>> from exactcagd import BezierCurve
    >>> arc = BezierCurve([[1, 0], [1, 1], [0, 1]], weights=[1, 1, 2])
    >>> [r.certified for r in line_roots(arc, (1, -1, 0))]       # x = y
    [True]
    """
    f = line_coefficients(curve, line)
    if all(x == 0 for x in f):
        raise InputError("the curve lies on the line: every parameter is a root")
    return bernstein_roots(f, method=method, tol=tol)


def derivative_coefficients(c: np.ndarray) -> np.ndarray:
    """Exact hodograph of a scalar Bernstein polynomial (notes 2.7) — convenience re-export."""
    return derivative(c)
