"""Figures 3-9 of Lasser & Bonneau, *Bézier Representation of Trim Curves*, in spirit.

For every figure: the surface (wireframe of exact float samples), the domain curves in
the parameter square, the exact image curves F(K(t)) (exact Bézier/rational Bézier form
of degree N(l+m), drawn by dense evaluation) and the G1 cubic approximation of section VIII
with its certified distance bound.  Figure 9 shows the biquintic free-form deformation.

Run:  python examples/lasser_figures.py [--tol 1/200] [--figures 3,4,...] [--out DIR]
Writes examples/output/lasser/figure{3..9}.png (or DIR/figure*.png) and prints the degrees and bounds.
"""

from __future__ import annotations

import argparse
from fractions import Fraction
from pathlib import Path

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

from exactcagd import BezierCurve, BSplineCurve  # noqa: E402
from exactcagd.composition import approximate_cubic, compose, compose_spline, ffd  # noqa: E402
from exactcagd.composition.cubic_approx import approximate_cubic_curve  # noqa: E402
from exactcagd.composition.paper_examples import FIGURES  # noqa: E402
from exactcagd.numeric.evaluation import evaluate  # noqa: E402

OUT = Path(__file__).resolve().parent / "output" / "lasser"


def sample_bezier(curve: BezierCurve, lo: float = 0.0, hi: float = 1.0, k: int = 300) -> np.ndarray:
    """Float points of an exact Bézier curve on [lo, hi] (vectorized de Casteljau of the float layer)."""
    return evaluate(curve, np.linspace(lo, hi, k), bound=False)


def sample_surface(surface, k: int = 13):
    """Float wireframe rows: the exact iso-curves u = i/(k-1) (de Casteljau in u), sampled in v."""
    return np.array([sample_bezier(surface.iso_u(Fraction(i, k - 1)), k=k) for i in range(k)])


def domain_pieces(curve):
    """Bézier curves of a domain curve (a Bézier curve, a B-spline, or a list of them)."""
    if isinstance(curve, list):
        return [c for item in curve for c in domain_pieces(item)]
    if isinstance(curve, BSplineCurve):
        return [piece for _, piece in curve.to_bezier()]
    return [curve]


def image_pieces(surface, curve):
    """Exact image curves: [(BezierCurve, (s0, s1) float local interval)]."""
    if isinstance(curve, list):
        return [p for item in curve for p in image_pieces(surface, item)]
    if isinstance(curve, BSplineCurve):
        result = compose_spline(surface, curve)
        return [(p.curve, tuple(float(x) for x in p.local_interval())) for p in result.pieces]
    return [(compose(surface, curve), (0.0, 1.0))]


def approximations(surface, curve, tol):
    if isinstance(curve, list):
        return [a for item in curve for a in approximations(surface, item, tol)]
    if isinstance(curve, BSplineCurve):
        return [approximate_cubic(surface, curve, tol)]
    return [approximate_cubic_curve(compose(surface, curve), tol)]


def draw_figure(number: int, tol, out: Path = OUT) -> dict:
    fig_data = FIGURES[number]()
    surface = fig_data["surface"]
    fig = plt.figure(figsize=(11, 5))
    ax2 = fig.add_subplot(1, 2, 1)
    ax3 = fig.add_subplot(1, 2, 2, projection="3d")
    grid = sample_surface(surface)
    for row in grid:
        ax3.plot(row[:, 0], row[:, 1], row[:, 2], color="0.8", lw=0.6)
    for col in grid.transpose(1, 0, 2):
        ax3.plot(col[:, 0], col[:, 1], col[:, 2], color="0.8", lw=0.6)
    report = {"figure": number, "surface degree": surface.degree, "curves": []}
    for k, curve in enumerate(fig_data["curves"]):
        color = f"C{k}"
        for j, piece in enumerate(domain_pieces(curve)):
            pts = sample_bezier(piece)
            ax2.plot(pts[:, 0], pts[:, 1], color=color, label=f"K{k + 1}(t)" if j == 0 else None)
        degrees = []
        for j, (image, (lo, hi)) in enumerate(image_pieces(surface, curve)):
            pts = sample_bezier(image, lo, hi)
            degrees.append(image.degree)
            ax3.plot(pts[:, 0], pts[:, 1], pts[:, 2], color=color, lw=2,
                     label=f"F(K{k + 1}(t)) exact, degree {image.degree}" if j == 0 else None)
        approxs = approximations(surface, curve, tol)
        bounds = [(len(a.segments), float(a.distance_bound)) for a in approxs]
        # one legend entry per curve for all its cubic approximations (one per Bezier piece of K)
        label = (f"G1 cubics of K{k + 1}: {sum(n for n, _ in bounds)} pieces, bound "
                 f"{max(b for _, b in bounds):.1e}")
        for seg in (seg for a in approxs for seg in a.segments):
            pts = sample_bezier(seg.curve, k=60)
            ax3.plot(pts[:, 0], pts[:, 1], pts[:, 2], color="k", lw=0.9, ls="--", label=label)
            label = None
        report["curves"].append({"image degrees": degrees, "cubics / certified bound": bounds})
    ax2.set_xlim(0, 1)
    ax2.set_ylim(0, 1)
    ax2.set_aspect("equal")
    ax2.set_xlabel("u")
    ax2.set_ylabel("v")
    ax2.legend(fontsize=8, loc="best")
    ax2.set_title("domain curves K(t) in [0,1]^2")
    ax3.set_xlabel("x")
    ax3.set_ylabel("y")
    ax3.set_zlabel("z")
    ax3.plot([], [], color="0.8", lw=0.6, label="surface F(u, v) (iso-curves)")
    ax3.legend(fontsize=7, loc="upper left", bbox_to_anchor=(-0.05, 1.0))
    ax3.set_title(f"F(K(t)) exact (colour), cubic approx. (dashed, tol {tol})", fontsize=9)
    fig.suptitle(fig_data["title"])
    out.mkdir(parents=True, exist_ok=True)
    fig.savefig(out / f"figure{number}.png", dpi=110)
    plt.close(fig)
    return report


def draw_figure9(tol, out: Path = OUT) -> dict:
    data = FIGURES[9]()
    lattice, identity = data["surface"], data["identity"]
    fig, (left, right) = plt.subplots(1, 2, figsize=(11, 5.5))
    for ax, lat, title in ((left, identity, "undeformed form, lattice (i/5, j/5)"), (right, lattice, "biquintic FFD (exact images, cubic approx. dashed)")):
        net = lat.net_array()
        fnet = np.vectorize(float, otypes=[float])(net)
        for i in range(fnet.shape[0]):
            ax.plot(fnet[i, :, 0], fnet[i, :, 1], color="0.75", lw=0.7)
            ax.plot(fnet[:, i, 0], fnet[:, i, 1], color="0.75", lw=0.7)
        ax.plot(fnet[..., 0].ravel(), fnet[..., 1].ravel(), ".", color="0.5", ms=3)
        ax.set_title(title, fontsize=10)
        ax.set_aspect("equal")
    report = {"figure": 9, "lattice degree": lattice.degree, "curves": []}
    for k, curve in enumerate(data["curves"]):
        pts = sample_bezier(curve)
        left.plot(pts[:, 0], pts[:, 1], color=f"C{k}", lw=2, label=f"curve {k + 1}, degree {curve.degree}")
        image = ffd(lattice, curve)
        pts = sample_bezier(image)
        approx = approximate_cubic_curve(image, tol)
        right.plot(pts[:, 0], pts[:, 1], color=f"C{k}", lw=2,
                   label=f"image {k + 1}, degree {image.degree}; {len(approx.segments)} cubic(s), bound {float(approx.distance_bound):.1e}")
        for j, seg in enumerate(approx.segments):
            p = sample_bezier(seg.curve, k=60)
            right.plot(p[:, 0], p[:, 1], "k--", lw=0.8, label="G1 cubic approximations" if (k, j) == (0, 0) else None)
        report["curves"].append({"domain degree": curve.degree, "image degree": image.degree, "true degree": image.true_degree(), "cubics": len(approx.segments), "bound": float(approx.distance_bound)})
    for ax in (left, right):
        ax.set_xlabel("x")
        ax.set_ylabel("y")
        ax.legend(fontsize=7, loc="best")
    fig.suptitle(data["title"])
    out.mkdir(parents=True, exist_ok=True)
    fig.savefig(out / "figure9.png", dpi=110)
    plt.close(fig)
    return report


def main(argv=None) -> list:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--tol", default="1/200", help="tolerance of the cubic approximation (exact rational)")
    parser.add_argument("--figures", default="3,4,5,6,7,8,9")
    parser.add_argument("--out", default=str(OUT), help="directory for the PNGs")
    args = parser.parse_args(argv)
    tol, out = Fraction(args.tol), Path(args.out)
    reports = []
    for number in (int(x) for x in args.figures.split(",")):
        report = draw_figure9(tol, out) if number == 9 else draw_figure(number, tol, out)
        print(report)
        reports.append(report)
    print(f"PNGs in {out}")
    return reports


if __name__ == "__main__":
    main()
