"""Shared helpers of the teaching scripts (examples/teach_*.py): float sampling for plots
and the output folder examples/output/teach/ (git-ignored)."""

from __future__ import annotations

from math import comb
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402,F401  (re-exported for the scripts)
import numpy as np  # noqa: E402

OUT = Path(__file__).resolve().parent / "output" / "teach"


def out_path(name: str) -> Path:
    OUT.mkdir(parents=True, exist_ok=True)
    return OUT / name


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
