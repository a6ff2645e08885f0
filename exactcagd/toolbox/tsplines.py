"""Cubic T-splines, exact (Sederberg's notes (003) 15.7).

A T-mesh is stored in knot-coordinate (pre-image) form on a grid of knot lines:
columns ``c`` with knot values ``s_values[c]`` and rows ``r`` with ``t_values[r]``
(equal neighbouring values are zero knot intervals).  Control points sit at grid nodes
``(c, r)``; ``s_edges`` are vertical segments ``(c, r0, r1)`` (constant ``s``), ``t_edges``
horizontal segments ``(r, c0, c1)``.

* Rule 1 (:meth:`TMesh.knot_vectors`): from a control point at ``(s_i2, t_i2)`` cast rays in
  the four parameter directions; the first two ``s``-edges (or control points) met to the
  right give ``s_i3, s_i4``, and so on.  Rays that leave the mesh continue through the
  phantom (end-condition) knots, by default copies of the boundary knot.
* (15.7)-(15.9): ``P(s, t) = sum w_i P_i B_i / sum w_i B_i`` with
  ``B_i = N[s_i](s) N[t_i](t)`` (:meth:`TMesh.evaluate`, :meth:`TMesh.blending`).
* 15.7.3-15.7.4: blending-function refinement and the matrix ``M_{1,2}`` (15.19)-(15.23)
  (:meth:`TMesh.to_bspline`, conversion to a tensor-product B-spline, 15.7.6).
* 15.7.5: the local refinement algorithm with its three violations (:meth:`TMesh.refine`).
* 15.7.6: standard / semi-standard / non-standard spaces (:meth:`TMesh.classify`).

>>> from exactcagd.toolbox.tsplines import TMesh
>>> m = TMesh.full_grid([0, 1, 2, 3], [0, 1, 2], lambda c, r: (c, r, c * r))
>>> m.knot_vectors((1, 1))
((mpq(0,1), mpq(0,1), mpq(1,1), mpq(2,1), mpq(3,1)), (mpq(0,1), mpq(0,1), mpq(1,1), mpq(2,1), mpq(2,1)))
"""

from __future__ import annotations

import numpy as np
from gmpy2 import mpq

from ..errors import DomainError, InputError, KnotError, WeightError
from ..exact.scalars import to_rational, to_rational_array
from .bspline_extras import basis_function, segment_blossom

__all__ = ["TMesh", "TensorSpline", "refine_indexed"]


def refine_indexed(idx5: tuple, k: int, value) -> list[tuple[object, tuple]]:
    """Insert the knot with index ``k`` into a blending function's index quintuple (15.14)-(15.17).

    ``value(i)`` gives the knot value of index ``i``; the position of ``k`` is decided by
    index (so zero knot intervals are handled), the coefficients by value:
    ``c = (k - s0)/(s3 - s0)`` (1 when ``k`` comes after ``s3``), ``d = (s4 - k)/(s4 - s1)``
    (1 when ``k`` comes before ``s1``); a zero denominator means the piece is identically
    zero and gets coefficient 0.
    """
    s = list(idx5)
    if k <= s[0] or k >= s[4] or k in s:
        return [(mpq(1), tuple(s))]
    merged = sorted(s + [k])
    v = [value(i) for i in s]
    kv = value(k)
    pos = merged.index(k)
    if pos > 3:
        c = mpq(1)
    else:
        c = (kv - v[0]) / (v[3] - v[0]) if v[3] != v[0] else mpq(0)
    if pos < 2:
        d = mpq(1)
    else:
        d = (v[4] - kv) / (v[4] - v[1]) if v[4] != v[1] else mpq(0)
    return [(c, tuple(merged[:5])), (d, tuple(merged[1:]))]


class TMesh:
    """A cubic T-spline: T-mesh topology, knot values, control points and weights.

    Parameters
    ----------
    s_values, t_values : knot values of the grid columns and rows (non-decreasing)
    points : dict ``{(c, r): point}`` -- control points at grid nodes
    s_edges : iterable of ``(c, r0, r1)``; t_edges : iterable of ``(r, c0, c1)``
    weights : dict ``{(c, r): w}``, optional (non-zero)
    phantom_s, phantom_t : ``(left, right)`` lists of two end-condition knots each, innermost
        first (default: the boundary knot repeated).
    """

    def __init__(self, s_values, t_values, points: dict, s_edges=(), t_edges=(), weights: dict | None = None, phantom_s=None, phantom_t=None):
        self.s_values = tuple(to_rational(x, where="s knot") for x in s_values)
        self.t_values = tuple(to_rational(x, where="t knot") for x in t_values)
        for name, vals in (("s", self.s_values), ("t", self.t_values)):
            if len(vals) < 2 or any(a > b for a, b in zip(vals, vals[1:])):
                raise KnotError(f"{name} knot values must be non-decreasing, at least two")
        C, R = len(self.s_values), len(self.t_values)
        self.points = {}
        for key, p in points.items():
            c, r = key
            if not (0 <= c < C and 0 <= r < R):
                raise InputError(f"control point at {key} is off the grid")
            self.points[(int(c), int(r))] = tuple(to_rational_array(p, where=f"P{key}"))
        if not self.points:
            raise InputError("no control points")
        dims = {len(p) for p in self.points.values()}
        if len(dims) != 1:
            raise InputError("control points of different dimension")
        self.weights = {}
        if weights is not None:
            for key in self.points:
                if key not in weights:
                    raise WeightError(f"missing weight at {key}")
                w = to_rational(weights[key], where=f"w{key}")
                if w == 0:
                    raise WeightError(f"zero weight at {key}")
                self.weights[key] = w
        self.s_edges = set()
        for c, r0, r1 in s_edges:
            if not (0 <= c < C and 0 <= r0 < r1 < R):
                raise InputError(f"bad s-edge {(c, r0, r1)}")
            self.s_edges.update((c, r) for r in range(r0, r1))  # unit segments (c, r)-(c, r+1)
        self.t_edges = set()
        for r, c0, c1 in t_edges:
            if not (0 <= r < R and 0 <= c0 < c1 < C):
                raise InputError(f"bad t-edge {(r, c0, c1)}")
            self.t_edges.update((c, r) for c in range(c0, c1))  # unit segments (c, r)-(c+1, r)
        self.phantom_s = self._phantom(phantom_s, self.s_values)
        self.phantom_t = self._phantom(phantom_t, self.t_values)
        for axis, vals in ((0, self.s_values), (1, self.t_values)):
            for v in set(vals):
                if vals.count(v) > 3 and v not in (vals[0], vals[-1]):
                    raise KnotError("an interior knot line of multiplicity > 3 (the curve would break)")

    @staticmethod
    def _phantom(given, vals):
        if given is None:
            return ([vals[0], vals[0]], [vals[-1], vals[-1]])
        left, right = given
        left = [to_rational(x, where="phantom knot") for x in left]
        right = [to_rational(x, where="phantom knot") for x in right]
        if len(left) != 2 or len(right) != 2:
            raise KnotError("two phantom knots on each side")
        if not (left[1] <= left[0] <= vals[0] and vals[-1] <= right[0] <= right[1]):
            raise KnotError("phantom knots must continue the knot sequence outwards")
        return (left, right)

    # ------------------------------------------------------------------ constructors
    @classmethod
    def full_grid(cls, s_values, t_values, point, weight=None, phantom_s=None, phantom_t=None) -> "TMesh":
        """A rectangular T-mesh (a tensor-product B-spline): control point ``point(c, r)`` at every node."""
        C, R = len(s_values), len(t_values)
        pts = {(c, r): point(c, r) for c in range(C) for r in range(R)}
        w = None if weight is None else {(c, r): weight(c, r) for c in range(C) for r in range(R)}
        return cls(
            s_values, t_values, pts, [(c, 0, R - 1) for c in range(C)], [(r, 0, C - 1) for r in range(R)], w, phantom_s, phantom_t
        )

    @classmethod
    def from_bspline(cls, control_net, knots_u, knots_v, weights=None) -> "TMesh":
        """The T-mesh of a cubic tensor-product B-spline (standard knot convention).

        Control point ``(i, j)`` sits at ``(knots_u[i+2], knots_v[j+2])``; the two outermost
        knots on each side become the phantom knots.
        """
        ku = [to_rational(x) for x in knots_u]
        kv = [to_rational(x) for x in knots_v]
        nu, nv = len(ku) - 4, len(kv) - 4
        net = to_rational_array(control_net, where="control_net")
        if net.shape[:2] != (nu, nv):
            raise InputError(f"net shape {net.shape[:2]} does not match cubic knot vectors ({nu}, {nv})")
        w = None if weights is None else (lambda c, r: weights[c][r])
        return cls.full_grid(
            ku[2 : nu + 2], kv[2 : nv + 2], lambda c, r: net[c, r], w,
            phantom_s=([ku[1], ku[0]], [ku[nu + 2], ku[nu + 3]]),
            phantom_t=([kv[1], kv[0]], [kv[nv + 2], kv[nv + 3]]),
        )

    # ------------------------------------------------------------------ knots (extended indices)
    @property
    def grid(self) -> tuple[int, int]:
        return len(self.s_values), len(self.t_values)

    def s_value(self, i: int):
        """Knot value of extended column index ``i`` (``-1, -2`` and ``C, C+1`` are phantoms)."""
        C = len(self.s_values)
        if 0 <= i < C:
            return self.s_values[i]
        if i < 0:
            return self.phantom_s[0][-i - 1]
        return self.phantom_s[1][i - C]

    def t_value(self, i: int):
        R = len(self.t_values)
        if 0 <= i < R:
            return self.t_values[i]
        if i < 0:
            return self.phantom_t[0][-i - 1]
        return self.phantom_t[1][i - R]

    def _s_hit(self, c: int, r: int, vertices) -> bool:
        return (c, r) in vertices or (c, r) in self.s_edges or (c, r - 1) in self.s_edges

    def _t_hit(self, c: int, r: int, vertices) -> bool:
        return (c, r) in vertices or (c, r) in self.t_edges or (c - 1, r) in self.t_edges

    def _rule1_indices(self, node, vertices=None) -> tuple[tuple, tuple]:
        vertices = self.points if vertices is None else vertices
        c, r = node
        C, R = self.grid

        def ray(start, stop, step, hit, outside):
            found = []
            i = start + step
            while len(found) < 2 and 0 <= i < stop:
                if hit(i):
                    found.append(i)
                i += step
            k = 0
            while len(found) < 2:
                found.append(outside(k))
                k += 1
            return found

        right = ray(c, C, 1, lambda i: self._s_hit(i, r, vertices), lambda k: C + k)
        left = ray(c, C, -1, lambda i: self._s_hit(i, r, vertices), lambda k: -1 - k)
        up = ray(r, R, 1, lambda j: self._t_hit(c, j, vertices), lambda k: R + k)
        down = ray(r, R, -1, lambda j: self._t_hit(c, j, vertices), lambda k: -1 - k)
        return (left[1], left[0], c, right[0], right[1]), (down[1], down[0], r, up[0], up[1])

    def knot_vectors(self, node) -> tuple[tuple, tuple]:
        """Rule 1: the knot vectors ``(s_i, t_i)`` (values) of the control point at ``node``."""
        if node not in self.points:
            raise InputError(f"no control point at {node}")
        si, ti = self._rule1_indices(node)
        return tuple(self.s_value(i) for i in si), tuple(self.t_value(j) for j in ti)

    # ------------------------------------------------------------------ evaluation (15.7)-(15.9)
    def weight(self, node):
        return self.weights.get(node, mpq(1))

    def blending(self, node, s, t):
        """``B_i(s, t) = N[s_i](s) N[t_i](t)`` (15.9)."""
        sk, tk = self.knot_vectors(node)
        return basis_function(sk, s) * basis_function(tk, t)

    def evaluate(self, s, t) -> tuple:
        """Exact point ``sum w_i P_i B_i / sum w_i B_i`` (15.7)."""
        s, t = to_rational(s, where="s"), to_rational(t, where="t")
        num, den = None, mpq(0)
        for node, p in self.points.items():
            b = self.blending(node, s, t) * self.weight(node)
            if b == 0:
                continue
            term = [b * x for x in p]
            num = term if num is None else [a + x for a, x in zip(num, term)]
            den += b
        if den == 0:
            raise DomainError(f"no blending function is non-zero at ({s}, {t}) (or the weights cancel)")
        return tuple(x / den for x in num)

    # ------------------------------------------------------------------ conversion (15.7.3, 15.7.6)
    def global_knots(self) -> tuple[tuple, tuple]:
        """Knot vectors ``S, T`` of the tensor-product B-spline space containing every ``B_i``.

        Every knot value appears as often as in the blending function that repeats it most.
        """
        out = []
        for axis in (0, 1):
            mult: dict = {}
            for node in self.points:
                kv = self.knot_vectors(node)[axis]
                for v in set(kv):
                    mult[v] = max(mult.get(v, 0), kv.count(v))
            out.append(tuple(v for v in sorted(mult) for _ in range(mult[v])))
        return out[0], out[1]

    def refinement_matrix(self) -> tuple[dict, tuple, tuple]:
        """``c_i^j`` of (15.21): ``B_i = sum_j c_i^j Btilde_j`` over the global tensor basis.

        Returns ``({node: {(a, b): c}}, S, T)`` with ``(a, b)`` the windows ``S[a:a+5] x T[b:b+5]``.
        """
        from .bspline_extras import refine_basis_function_multi

        S, T = self.global_knots()
        s_index = {S[a : a + 5]: a for a in range(len(S) - 4)}
        t_index = {T[b : b + 5]: b for b in range(len(T) - 4)}
        out = {}
        for node in self.points:
            sk, tk = self.knot_vectors(node)
            alpha = {s_index[ks]: c for c, ks in refine_basis_function_multi(sk, S)}
            beta = {t_index[ks]: c for c, ks in refine_basis_function_multi(tk, T)}
            out[node] = {(a, b): ca * cb for a, ca in alpha.items() for b, cb in beta.items()}
        return out, S, T

    def to_bspline(self) -> "TensorSpline":
        """The equivalent tensor-product (rational) B-spline, (15.19)-(15.23) and 15.7.6.

        The homogeneous control point of ``Btilde_j`` is ``sum_i c_i^j (w_i P_i, w_i)``.
        """
        M, S, T = self.refinement_matrix()
        d = len(next(iter(self.points.values())))
        hom = np.empty((len(S) - 4, len(T) - 4, d + 1), dtype=object)
        hom[...] = mpq(0)
        for node, row in M.items():
            w = self.weight(node)
            h = np.array([w * x for x in self.points[node]] + [w], dtype=object)
            for (a, b), c in row.items():
                hom[a, b] += c * h
        return TensorSpline(hom, S, T)

    def classify(self) -> str:
        """``"standard"`` (all ``w_i = 1`` give ``sum B_i == 1``), ``"semi-standard"`` (only other
        weights do) or ``"non-standard"`` (no weights do) on the domain of the global knot
        vectors (15.7.6); decided by exact linear algebra on the matrix ``M``."""
        import sympy

        M, S, T = self.refinement_matrix()
        nodes = sorted(self.points)
        rows = sorted({ab for row in M.values() for ab in row if _meets_domain(S, ab[0]) and _meets_domain(T, ab[1])})
        A = sympy.Matrix([[sympy.Rational(str(M[n].get(ab, 0))) for n in nodes] for ab in rows])
        ones_rows = sympy.Matrix([1] * len(rows))
        if A * sympy.Matrix([1] * len(nodes)) == ones_rows:
            return "standard"
        try:
            sol, params = A.gauss_jordan_solve(ones_rows)
        except ValueError:
            return "non-standard"
        return "semi-standard"

    # ------------------------------------------------------------------ local refinement (15.7.5)
    def refine(self, new_nodes, max_rounds: int = 10000) -> "TMesh":
        """Local refinement: insert control points at grid nodes without changing the surface.

        Topology phase (15.7.5): the new points are inserted with no blending function;
        then, repeatedly, a blending function missing a knot that Rule 1 dictates
        (Violation 1) is split by (15.14)-(15.17), and a blending function with a knot
        Rule 1 does not dictate (Violation 2) makes a control point appear at that knot on
        the function's central row / column.  Geometry phase (15.23): the new control point
        is ``sum c_i^j`` (homogeneous old points) over the scaled functions that ended there.

        Control points added by the algorithm carry no new edges: Rule 1 counts control
        points as knot crossings.
        """
        C, R = self.grid
        vertices = set(self.points)
        for node in new_nodes:
            c, r = int(node[0]), int(node[1])
            if not (0 <= c < C and 0 <= r < R):
                raise InputError(f"node {node} is off the grid (add knot lines with with_s_line/with_t_line)")
            vertices.add((c, r))
        pieces: dict = {}
        for node in self.points:
            si, ti = self._rule1_indices(node)
            pieces[(si, ti, node)] = mpq(1)
        for _ in range(max_rounds):
            action = None
            for (si, ti, src), coef in pieces.items():
                center = (si[2], ti[2])
                if center not in vertices:
                    vertices.add(center)  # violation 3 the other way round: a function without a point
                    action = "vertex"
                    break
                rs, rt = self._rule1_indices(center, vertices)
                miss_s = [k for k in rs if si[0] < k < si[4] and k not in si]
                miss_t = [k for k in rt if ti[0] < k < ti[4] and k not in ti]
                if miss_s or miss_t:
                    del pieces[(si, ti, src)]
                    if miss_s:
                        parts = [(c, ks, ti) for c, ks in refine_indexed(si, miss_s[0], self.s_value)]
                    else:
                        parts = [(c, si, ks) for c, ks in refine_indexed(ti, miss_t[0], self.t_value)]
                    for c, ks, kt in parts:
                        if c != 0:
                            key = (ks, kt, src)
                            pieces[key] = pieces.get(key, mpq(0)) + coef * c
                    action = "split"
                    break
                extra_s = [k for k in si if k not in rs]
                extra_t = [k for k in ti if k not in rt]
                if extra_s or extra_t:
                    node = (extra_s[0], center[1]) if extra_s else (center[0], extra_t[0])
                    if not (0 <= node[0] < C and 0 <= node[1] < R):
                        raise KnotError(f"refinement needs a control point at phantom knot {node}")
                    vertices.add(node)
                    action = "vertex"
                    break
            if action is None:
                break
        else:  # pragma: no cover
            raise RuntimeError("local refinement did not terminate")
        # geometry phase
        d = len(next(iter(self.points.values())))
        acc: dict = {}
        for (si, ti, src), coef in pieces.items():
            center = (si[2], ti[2])
            w = self.weight(src)
            h = [coef * w * x for x in self.points[src]] + [coef * w]
            acc[center] = h if center not in acc else [a + b for a, b in zip(acc[center], h)]
        missing = vertices - set(acc)
        if missing:
            raise KnotError(f"control points {sorted(missing)} received no blending function (violation 3)")
        pts, wts = {}, {}
        for node, h in acc.items():
            if h[-1] == 0:
                raise WeightError(f"refined control point at {node} has weight zero")
            pts[node] = [x / h[-1] for x in h[:-1]]
            wts[node] = h[-1]
        rational = bool(self.weights) or any(w != 1 for w in wts.values())
        s_edges = [(c, r, r + 1) for c, r in self.s_edges]
        t_edges = [(r, c, c + 1) for c, r in self.t_edges]
        out = TMesh(self.s_values, self.t_values, pts, s_edges, t_edges, wts if rational else None,
                    (self.phantom_s[0], self.phantom_s[1]), (self.phantom_t[0], self.phantom_t[1]))
        for node in out.points:  # every piece that ended at a node must be the node's Rule-1 function
            si, ti = out._rule1_indices(node)
            for (ps, pt, _), _c in pieces.items():
                if (ps[2], pt[2]) == node and (ps, pt) != (si, ti):  # pragma: no cover - algorithm invariant
                    raise KnotError(f"refinement left a non-Rule-1 blending function at {node}")
        return out

    def with_s_line(self, value) -> "TMesh":
        """A copy with an extra (empty) knot column at ``value`` (no edges, no points)."""
        return self._with_line(0, value)

    def with_t_line(self, value) -> "TMesh":
        return self._with_line(1, value)

    def _with_line(self, axis, value):
        value = to_rational(value)
        vals = list(self.s_values if axis == 0 else self.t_values)
        pos = sum(1 for v in vals if v <= value)
        vals.insert(pos, value)
        shift = lambda i: i + 1 if i >= pos else i  # noqa: E731
        if axis == 0:
            pts = {(shift(c), r): p for (c, r), p in self.points.items()}
            w = {(shift(c), r): x for (c, r), x in self.weights.items()} or None
            se = [(shift(c), r, r + 1) for c, r in self.s_edges]
            te = [(r, shift(c), shift(c + 1)) for c, r in self.t_edges]
            return TMesh(vals, self.t_values, pts, se, te, w, self.phantom_s, self.phantom_t)
        pts = {(c, shift(r)): p for (c, r), p in self.points.items()}
        w = {(c, shift(r)): x for (c, r), x in self.weights.items()} or None
        te = [(shift(r), c, c + 1) for c, r in self.t_edges]
        se = [(c, shift(r), shift(r + 1)) for c, r in self.s_edges]
        return TMesh(self.s_values, vals, pts, se, te, w, self.phantom_s, self.phantom_t)

    def __repr__(self) -> str:
        return f"<TMesh grid={self.grid} control_points={len(self.points)}>"


def _meets_domain(K: tuple, a: int) -> bool:
    """Does the support ``[K[a], K[a+4]]`` meet the open domain ``(K[3], K[-4])``?"""
    lo, hi = K[3], K[len(K) - 4]
    return K[a] < hi and K[a + 4] > lo and lo < hi


class TensorSpline:
    """A tensor-product cubic B-spline in homogeneous form on arbitrary knot vectors (exact).

    ``hom`` has shape ``(len(S) - 4, len(T) - 4, d + 1)``; the surface is defined for
    ``s`` in ``[S[3], S[-4]]`` and ``t`` in ``[T[3], T[-4]]``.
    """

    def __init__(self, hom: np.ndarray, S: tuple, T: tuple):
        self.hom, self.S, self.T = hom, tuple(S), tuple(T)

    @property
    def domain(self):
        S, T = self.S, self.T
        return (S[3], S[len(S) - 4]), (T[3], T[len(T) - 4])

    def _eval_axis(self, arr, K, x):
        p = 3
        n = arr.shape[0]
        lo, hi = K[p], K[n]
        if not lo <= x <= hi:
            raise DomainError(f"parameter {x} outside [{lo}, {hi}]")
        spans = [l for l in range(p, n) if K[l] < K[l + 1]]
        l = spans[-1] if x == hi else max(l for l in spans if K[l] <= x)
        return segment_blossom(arr[l - p : l + 1], K[l - p + 1 : l + p + 1], [x] * p)

    def evaluate(self, s, t) -> tuple:
        s, t = to_rational(s, where="s"), to_rational(t, where="t")
        col = self._eval_axis(self.hom, self.S, s)
        val = self._eval_axis(col, self.T, t)
        if val[-1] == 0:
            raise DomainError("weight zero")
        return tuple(x / val[-1] for x in val[:-1])

    def is_polynomial(self) -> bool:
        """All homogeneous weights equal to 1 (the weight function is identically 1)."""
        return all(x == 1 for x in self.hom[..., -1].reshape(-1))

    def to_bspline_surface(self):
        """A foundation :class:`~exactcagd.geometry.bspline.BSplineSurface` (clamped knots, positive weights)."""
        from ..geometry.bspline import BSplineSurface

        w = self.hom[..., -1]
        pts = self.hom[..., :-1] / w[..., None]
        return BSplineSurface(pts, self.S, self.T, weights=None if self.is_polynomial() else w)
