"""Tables 1-4 of Yang et al., "G1 continuous approximate curves on NURBS surfaces" (CAD 2012),
recomputed with exactcagd on stand-in models -- one command.

The paper's face (17 x 17 control points), Venus (145 x 55) and car roof are not available.
Stand-ins (``exactcagd.curves_on_surfaces.samples``), all exact rational data, rebuilt
identically on every run:

* face  (Tables 1, 2): bicubic clamped B-spline, 17 x 17 control points at the Greville
  abscissae of uniform knots on [0,1]^2 (so x = u, y = v), heights = a smooth relief (Gaussian
  head, nose, eyes, mouth) rounded to multiples of 2^-12 (14 x 14 Bezier patches);
  domain curve: closed C2 cubic NURBS curve from 8 periodic control points on a wobbly
  ellipse around (1/2, 1/2) (coordinates rounded to 1/1000, weights 1 and 3/2), converted
  exactly to clamped form on [0, 1] by blossoming (11 control points, 8 Bezier pieces);
* venus (Table 3): the same construction with 145 x 55 control points (142 x 52 patches) and a
  relief with folds and two details; closed cubic NURBS domain curve from 12 control points;
* roof  (Table 4): 12 x 10 control points, a gently crowned roof; open cubic B-spline domain
  curve with 19 polynomial pieces (the paper's "cubic curve consisting of 19 segments").

Methods: polyline (ref. [2]), hyperbola (ref. [15]) -- both with angle tolerance eps_T = 1 deg --
and parabola (the paper, G1), for eps_D = 1e-1 ... 1e-5; the "Exact" column is the exact
composition S(D(t)) (``exactcagd.composition.compose_spline``: one piece per Bezier piece of D
inside one patch).  "Distance to S" is 0 for every method: all segments are exact images
X(u(t), v(t)) of domain curves (checked exactly in the tests).  "bound" is the certified upper
bound of the Hausdorff distance to the exact image curve.  Times are Python exact-arithmetic
seconds (the paper: C++ milliseconds on a 2 GHz Pentium IV), so only their ratios compare.

Usage::

    python examples/yang_tables.py            # all 3 models x 5 tolerances x 3 methods
    python examples/yang_tables.py --quick    # face + venus, eps_D in {1e-1, 1e-3}; ~2-3 minutes

``--budget S`` stops a single run after S seconds (recorded as "> S s", default 90 / 45 quick).
Writes ``examples/output/yang/tables.md``, ``results.json`` and one PNG per result (model,
method, eps_D) to ``examples/output/yang/`` (git-ignored), and the committed copy of the tables,
with the paper's printed figures next to ours, to ``benchmarks/results/full/yang_tables.md`` (full runs only).
"""

from __future__ import annotations

import argparse
import json
import sys
import time
from pathlib import Path

import numpy as np

from exactcagd.curves_on_surfaces import approximate
from exactcagd.curves_on_surfaces.samples import analytic_surface, closed_domain_curve, open_domain_curve

ROOT = Path(__file__).resolve().parent.parent
sys.path.insert(0, str(ROOT))
from benchmarks._budget import run_with_budget as timed_run  # noqa: E402
from benchmarks._common import machine  # noqa: E402
OUT = ROOT / "examples" / "output" / "yang"
COMMITTED = ROOT / "benchmarks" / "results" / "full" / "yang_tables.md"
METHODS = ("polyline", "hyperbola", "parabola")
TOLERANCES = ("1e-1", "1e-2", "1e-3", "1e-4", "1e-5")
PAPER_T1 = {"polyline": [443, 448, 459, 700, 2118], "hyperbola": [63, 69, 70, 110, 230], "parabola": [43, 44, 59, 77, 131]}
PAPER = {  # Tables 2-4 at eps_D = 1e-3 (eps_T = 1 deg): segments, degree, time (ms)
    "face": {"table": "Table 2", "segments": (43, 275, 82, 58), "degree": (18, 6, 6, 9), "ms": (2.1, 40, 36, 31)},
    "venus": {"table": "Table 3", "segments": (70, 367, 149, 96), "degree": (18, 6, 6, 9), "ms": (3.6, 73, 59, 47)},
    "roof": {"table": "Table 4", "segments": (28, 993, 127, 50), "degree": (18, 6, 6, 9), "ms": (1.5, 189, 54, 21)},
}


def models(names) -> dict:
    make = {
        "face": lambda: (analytic_surface(17, 17, "face"), closed_domain_curve(8), "bicubic 17x17, closed cubic NURBS with 8 control points"),
        "venus": lambda: (analytic_surface(145, 55, "venus"), closed_domain_curve(12), "bicubic 145x55, closed cubic NURBS with 12 control points"),
        "roof": lambda: (analytic_surface(12, 10, "roof"), open_domain_curve(19), "bicubic 12x10, open cubic B-spline with 19 pieces"),
    }
    return {name: make[name]() for name in names}


def exact_column(surface, curve, budget: float) -> dict:
    from exactcagd.composition import compose_spline

    result, seconds = timed_run(lambda: compose_spline(surface, curve), budget)
    if result is None:
        return {"segments": None, "degree": None, "seconds": seconds}
    return {"segments": len(result.pieces), "degree": max(p.curve.degree for p in result.pieces), "seconds": seconds}


def run(names, tolerances, budget: float, pictures: bool) -> dict:
    results = {}
    for name, (surface, curve, how) in models(names).items():
        entry = {"how": how, "runs": {}, "exact": exact_column(surface, curve, budget)}
        ex = entry["exact"]
        print(f"{name:6s} exact     segments={ex['segments']} degree={ex['degree']} {ex['seconds']:.1f}s", flush=True)
        for tol in tolerances:
            for method in METHODS:
                r, seconds = timed_run(lambda: approximate(surface, curve, tol, method, angle_tol=1), budget)
                if r is None:
                    entry["runs"][f"{method}@{tol}"] = {"timeout": budget}
                    print(f"{name:6s} {method:9s} eps={tol:5s} stopped after {budget:.0f} s", flush=True)
                    continue
                entry["runs"][f"{method}@{tol}"] = {
                    "segments": len(r),
                    "degree": r.degree,
                    "bound": float(r.distance_bound),
                    "continuity": r.continuity,
                    "max_angle": r.max_joint_angle,
                    "seconds": seconds,
                    "kinds": {k: r.kinds.count(k) for k in sorted(set(r.kinds))},
                }
                print(f"{name:6s} {method:9s} eps={tol:5s} segments={len(r):5d} degree={r.degree} "
                      f"bound={float(r.distance_bound):.3e} {r.continuity} {seconds:.1f}s", flush=True)
                if pictures:
                    plot(name, method, tol, surface, curve, r)
        results[name] = entry
        (OUT / "results.json").write_text(json.dumps(results, indent=1, default=str))
    return results


# ----------------------------------------------------------------------------- pictures
def plot(name: str, method: str, tol: str, surface, curve, result) -> None:
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    fig = plt.figure(figsize=(11, 5))
    ax = fig.add_subplot(1, 2, 1)
    u_lines, v_lines = surface.breakpoints()
    for x in u_lines:
        ax.axvline(float(x), color="0.9", lw=0.4)
    for y in v_lines:
        ax.axhline(float(y), color="0.9", lw=0.4)
    lo, hi = curve.domain
    pts = np.array([[float(c) for c in curve.evaluate(lo + (hi - lo) * float(t))] for t in np.linspace(0, 1, 300)])
    ax.plot(pts[:, 0], pts[:, 1], color="0.7", lw=3, label="domain curve D(t)")
    colors = {"s-parabola": "tab:red", "t-parabola": "tab:blue", "s-hyperbola": "tab:orange", "t-hyperbola": "tab:purple", "segment": "tab:green"}
    ts = np.linspace(0, 1, 12)
    for seg, kind in zip(result.domain_segments, result.kinds):
        p = _float_curve(seg, ts)
        ax.plot(p[:, 0], p[:, 1], color=colors.get(kind, "k"), lw=0.9)
        ax.plot(p[[0, -1], 0], p[[0, -1], 1], "k.", ms=1.5)
    for kind in sorted(set(result.kinds)):  # one legend entry per segment kind
        ax.plot([], [], color=colors.get(kind, "k"), lw=0.9, label=f"{kind} ({result.kinds.count(kind)})")
    ax.plot([], [], "k.", ms=3, label="segment joints")
    ax.set_xlim(pts[:, 0].min() - 0.03, pts[:, 0].max() + 0.03)
    ax.set_ylim(pts[:, 1].min() - 0.03, pts[:, 1].max() + 0.03)
    ax.set_aspect("equal")
    ax.set_xlabel("u")
    ax.set_ylabel("v")
    ax.legend(fontsize=7, loc="center")
    ax.set_title(f"{name}: {method}, eps_D = {tol}: {len(result)} segments", fontsize=9)
    ax3 = fig.add_subplot(1, 2, 2, projection="3d")
    _draw_surface(ax3, surface)
    for seg, kind in zip(result.segments, result.kinds):
        p = _float_curve(seg, ts)
        ax3.plot(p[:, 0], p[:, 1], p[:, 2], color=colors.get(kind, "k"), lw=1.0)
    for kind in sorted(set(result.kinds)):
        ax3.plot([], [], color=colors.get(kind, "k"), lw=1.0, label=f"image of {kind} segments")
    ax3.set_xlabel("x")
    ax3.set_ylabel("y")
    ax3.set_zlabel("z")
    ax3.legend(fontsize=7, loc="upper left")
    ax3.set_title(f"image on S: degree {result.degree}, {result.continuity}, bound {float(result.distance_bound):.1e}", fontsize=9)
    fig.tight_layout()
    fig.savefig(OUT / f"{name}_{method}_{tol}.png", dpi=90)
    plt.close(fig)


def _draw_surface(ax3, surface, lines: int = 17) -> None:
    """The surface as a light wireframe of float samples (plots only), with a legend entry."""
    from exactcagd.numeric.sampling import sample_surface

    (u0, u1), (v0, v1) = surface.domain
    grid = sample_surface(surface, np.linspace(float(u0), float(u1), lines), np.linspace(float(v0), float(v1), lines))
    ax3.plot_wireframe(grid[..., 0], grid[..., 1], grid[..., 2], color="0.75", lw=0.4)
    ax3.plot([], [], color="0.75", lw=0.4, label="surface S (wireframe)")


def _float_curve(curve, ts) -> np.ndarray:
    """Float points of an exact curve (homogeneous de Casteljau in float64; plots only)."""
    h = np.vectorize(float, otypes=[float])(curve.homogeneous())
    level = np.broadcast_to(h, (len(ts),) + h.shape).copy()
    t = np.asarray(ts)[:, None, None]
    while level.shape[1] > 1:
        level = (1 - t) * level[:, :-1] + t * level[:, 1:]
    return level[:, 0, :-1] / level[:, 0, -1:]


# ----------------------------------------------------------------------------- tables
def _cell(run: dict | None, key: str, fmt: str = "{}") -> str:
    if not run:
        return "-"
    if "timeout" in run:
        return f"> {run['timeout']:.0f} s"
    return fmt.format(run[key])


def markdown(results: dict, tolerances, quick: bool, wall: float) -> str:
    lines = ["# Yang et al. (2012), Tables 1-4 recomputed on exactcagd stand-in models", ""]
    lines += [
        "Generated by `python examples/yang_tables.py" + (" --quick" if quick else "") + f"` in {wall / 60:.1f} min "
        f"on {machine()} (shared with other jobs: single times can be inflated by load). "
        "Models, methods and how they were made: see the docstring of `examples/yang_tables.py`. "
        "Our numbers come from stand-in surfaces and curves (the paper's face, Venus and car models are not "
        "available), so segment counts compare in trend only. Times: Python exact arithmetic, seconds "
        "(paper: C++, milliseconds). `bound` = certified upper bound of the Hausdorff distance to the exact "
        "image S(D(t)); every segment lies exactly on S (distance to S = 0). Continuity: `G1` is checked "
        "exactly at every joint (cross products zero in Q(sqrt(Delta))); `eps_T-G1` = max joint angle <= 1 deg.",
        "",
    ]
    if "face" in results:
        runs = results["face"]["runs"]
        lines += ["## Table 1: segments of the domain curve (face / 17x17, closed 8-point curve)", ""]
        lines.append("| eps_D | polyline | hyperbola | parabola | paper: polyline | paper: hyperbola | paper: parabola |")
        lines.append("|---|---|---|---|---|---|---|")
        for tol in tolerances:
            i = TOLERANCES.index(tol)
            cells = [_cell(runs.get(f"{m}@{tol}"), "segments") for m in METHODS]
            lines.append(f"| {tol} | " + " | ".join(cells) + " | " + " | ".join(str(PAPER_T1[m][i]) for m in METHODS) + " |")
        lines.append("")
    for name, entry in results.items():
        paper = PAPER[name]
        ex = entry["exact"]
        runs = entry["runs"]
        lines += [f"## {paper['table']} analogue: {name} ({entry['how']})", ""]
        lines.append("| | Exact | Polyline | Hyperbola | Parabola |")
        lines.append("|---|---|---|---|---|")
        r = [runs.get(f"{m}@1e-3") for m in METHODS]
        if any(r):
            lines.append("| Tolerance | - | 1e-3 / 1 deg | 1e-3 / 1 deg | 1e-3 |")
            lines.append(f"| Degree | {ex['degree']} | " + " | ".join(_cell(x, "degree") for x in r) + " |")
            lines.append(f"| Number of segments | {ex['segments']} | " + " | ".join(_cell(x, "segments") for x in r) + " |")
            lines.append("| Distance to S | 0 | 0 | 0 | 0 |")
            lines.append("| Certified distance to exact curve | 0 | " + " | ".join(_cell(x, "bound", "{:.2e}") for x in r) + " |")
            cont = [("-" if not x or "timeout" in x else (x["continuity"] if x["continuity"] == "G1" else f"{x['max_angle']:.2f} deg-G1")) for x in r]
            lines.append("| Continuity | G1 | " + " | ".join(cont) + " |")
            lines.append(f"| Time (s) | {ex['seconds']:.2f} | " + " | ".join(_cell(x, "seconds", "{:.1f}") for x in r) + " |")
        s, d, ms = paper["segments"], paper["degree"], paper["ms"]
        lines.append(f"| *paper: degree* | {d[0]} | {d[1]} | {d[2]} | {d[3]} |")
        lines.append(f"| *paper: segments* | {s[0]} | {s[1]} | {s[2]} | {s[3]} |")
        lines.append(f"| *paper: time (ms)* | {ms[0]} | {ms[1]} | {ms[2]} | {ms[3]} |")
        lines.append("")
        lines.append(f"All tolerances ({name}): segments / certified bound / seconds")
        lines.append("")
        lines.append("| eps_D | polyline | hyperbola | parabola |")
        lines.append("|---|---|---|---|")
        for tol in tolerances:
            cells = []
            for m in METHODS:
                x = runs.get(f"{m}@{tol}")
                cells.append("-" if not x else (f"> {x['timeout']:.0f} s" if "timeout" in x else f"{x['segments']} / {x['bound']:.1e} / {x['seconds']:.1f}"))
            lines.append(f"| {tol} | " + " | ".join(cells) + " |")
        lines.append("")
    lines.append("Degrees: polyline and hyperbola images have degree m + n = 6, parabola images "
                 "max(2m + n, m + 2n) = 9, the exact image (m + n) d = 18 (bicubic surface, cubic curve), as printed.")
    return "\n".join(lines) + "\n"


def picture(name: str, method: str, tol: str, out: Path = OUT) -> Path:
    """Compute and draw one result (model, method, eps_D) into ``out``; no tables."""
    global OUT
    ((surface, curve, _how),) = models([name]).values()
    result = approximate(surface, curve, tol, method, angle_tol=1)
    OUT = out
    out.mkdir(parents=True, exist_ok=True)
    plot(name, method, tol, surface, curve, result)
    print(f"{name} {method} eps_D={tol}: {len(result)} segments, degree {result.degree}, "
          f"bound {float(result.distance_bound):.3e}; wrote {out / f'{name}_{method}_{tol}.png'}")
    return out / f"{name}_{method}_{tol}.png"


def main(argv=None) -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="face and venus, eps_D in {1e-1, 1e-3}")
    parser.add_argument("--budget", type=float, default=None, help="seconds allowed per single run")
    parser.add_argument("--no-pictures", action="store_true")
    parser.add_argument("--no-commit-copy", action="store_true", help="do not rewrite benchmarks/results/full/yang_tables.md")
    parser.add_argument("--picture", metavar="MODEL:METHOD:EPS", help="only draw one result, e.g. face:parabola:1e-2 (the docs gallery)")
    parser.add_argument("--out", help="folder for --picture's PNG (default examples/output/yang)")
    args = parser.parse_args(argv)
    if args.picture:
        return picture(*args.picture.split(":"), out=Path(args.out) if args.out else OUT)
    OUT.mkdir(parents=True, exist_ok=True)
    names = ("face", "venus") if args.quick else ("face", "venus", "roof")
    tolerances = ("1e-1", "1e-3") if args.quick else TOLERANCES
    budget = args.budget or (45.0 if args.quick else 90.0)
    start = time.perf_counter()
    results = run(names, tolerances, budget, not args.no_pictures)
    text = markdown(results, tolerances, args.quick, time.perf_counter() - start)
    (OUT / "tables.md").write_text(text)
    if not (args.no_commit_copy or args.quick):  # the committed copy holds the full run only
        COMMITTED.parent.mkdir(parents=True, exist_ok=True)
        COMMITTED.write_text(text)
    print(f"wrote {OUT / 'tables.md'}" + ("" if (args.no_commit_copy or args.quick) else f" and {COMMITTED}"))


if __name__ == "__main__":
    main()
