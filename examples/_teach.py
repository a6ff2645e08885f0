"""Shared helpers of the teaching scripts (examples/teach_*.py): float sampling for plots,
the output folder examples/output/teach/ (git-ignored; ``EXACTCAGD_EXAMPLES_OUT`` moves it,
as the documentation build does) and :func:`tex`, which prints a derivation step and, for the
documentation, records it typeset (sympy LaTeX) in ``<script>.steps.json`` next to the pictures."""

from __future__ import annotations

import atexit
import json
import os
import sys
from math import comb
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402,F401  (re-exported for the scripts)
import numpy as np  # noqa: E402

OUT = Path(os.environ.get("EXACTCAGD_EXAMPLES_OUT") or Path(__file__).resolve().parent / "output" / "teach")
#: the derivation as the docs show it: [{"title": ..., "items": [{"label", "latex"}]}]
STEPS: list[dict] = []


def out_path(name: str) -> Path:
    """Where to save picture ``name``; called as ``fig.savefig(out_path(name))``, so the open
    figures are finished here: every unlabelled axis gets its coordinate name (x, y, z)."""
    OUT.mkdir(parents=True, exist_ok=True)
    for number in plt.get_fignums():
        fig = plt.figure(number)
        label_axes(fig)
        if type(fig.get_layout_engine()).__name__ != "ConstrainedLayoutEngine":
            fig.tight_layout()  # again: room for the labels just added
    return OUT / name


def label_axes(fig) -> None:
    """Name the unlabelled axes of the geometric views of ``fig`` (3-D views, and 2-D views drawn
    with equal aspect): x, y and z (a reader must know which coordinate is up).  Graphs of
    functions keep their own labels."""
    for ax in fig.axes:
        is_3d = hasattr(ax, "get_zlabel")
        if not is_3d and ax.get_aspect() not in (1, 1.0, "equal"):
            continue
        if not ax.get_xlabel():
            ax.set_xlabel("x")
        if not ax.get_ylabel():
            ax.set_ylabel("y")
        if is_3d and not ax.get_zlabel():
            ax.set_zlabel("z")


def sample(curve, k: int = 300, lo: float = 0.0, hi: float = 1.0) -> np.ndarray:
    """Float points of an exact (rational) Bézier curve, for drawing only."""
    hom = np.vectorize(float, otypes=[float])(curve.homogeneous())
    n = curve.degree
    t = np.linspace(lo, hi, k)[:, None]
    basis = np.hstack([comb(n, i) * t**i * (1 - t) ** (n - i) for i in range(n + 1)])
    h = basis @ hom
    return h[:, :-1] / h[:, -1:]


def polygon(curve) -> np.ndarray:
    return np.array([[float(x) for x in p] for p in curve.control_points])


def step(title: str) -> None:
    print(f"\n== {title}")
    STEPS.append({"title": title, "items": []})


def tex(label: str, value, echo: bool = True) -> None:
    """Print ``label = value`` (unless ``echo=False``: the script printed it already) and record
    the value typeset by sympy for the docs page.

    ``value`` is anything sympy understands (expressions, matrices; mpq and nested lists of them).
    """
    import sympy as sp

    if echo:
        print(label, "=", fmt(value))
    try:
        expr = sp.sympify(_sympy_ready(value))
        if expr.atoms(sp.Float) and not isinstance(value, float):
            raise TypeError("an exact value came out as a float")  # show the exact text instead
        latex = sp.latex(expr)
    except (sp.SympifyError, TypeError, AttributeError):
        latex = r"\text{" + fmt(value).replace("_", r"\_") + "}"
    if not STEPS:
        STEPS.append({"title": "", "items": []})
    STEPS[-1]["items"].append({"label": label, "latex": latex})


def _sympy_ready(value):
    """mpq -> sympy Rational, recursively (sympify does not know gmpy2 types)."""
    import sympy as sp
    from gmpy2 import mpq

    if isinstance(value, type(mpq(0))):
        return sp.Rational(int(value.numerator), int(value.denominator))
    if hasattr(value, "to_sympy"):  # exact numbers and objects (Q(sqrt D), curves): never via float
        return value.to_sympy()
    if isinstance(value, np.ndarray):
        value = value.tolist()
    if isinstance(value, (list, tuple)):
        items = [_sympy_ready(v) for v in value]
        return sp.Matrix([items]) if items and not isinstance(items[0], (list, sp.MatrixBase)) else sp.Matrix(items)
    return value


@atexit.register
def _write_steps() -> None:
    if STEPS and os.environ.get("EXACTCAGD_EXAMPLES_OUT"):
        name = Path(sys.argv[0]).stem
        Path(OUT).mkdir(parents=True, exist_ok=True)
        (Path(OUT) / f"{name}.steps.json").write_text(json.dumps(STEPS, indent=1))


def fmt(x):
    """Readable exact values: mpq -> 'p/q', recursively through tuples, lists and arrays."""
    from gmpy2 import mpq

    if isinstance(x, type(mpq(0))):
        return str(x.numerator) if x.denominator == 1 else f"{x.numerator}/{x.denominator}"
    if isinstance(x, np.ndarray):
        return fmt(x.tolist())
    if isinstance(x, (list, tuple)):
        inner = ", ".join(fmt(v) for v in x)
        return f"({inner})" if isinstance(x, tuple) else f"[{inner}]"
    return str(x)
