"""The lazy planner's effect on a large scene (issue: scenes).

A bicubic B-spline surface with 145 x 55 control points (142 x 52 = 7384 Bézier patches)
and one cubic trim curve.  The planned run extracts only the patches the curve crosses
(by blossoming) and composes the pieces; the eager run extracts every patch by knot
insertion first, as a non-lazy pipeline would, then composes.  Both must give the same
exact pieces.  Time and peak memory (tracemalloc) are compared in the same process.

    python -m benchmarks.bench_scenes [--quick]
"""

from __future__ import annotations

import tempfile

from ._common import markdown_table, measure, parse_quick, write_result


def large_scene(nu: int = 145, nv: int = 55) -> dict:
    """The benchmark scene as a dict: exact grid surface, uniform clamped knots, one trim curve."""
    def knots(n):
        inner = [f"{k}/{n - 3}" for k in range(1, n - 3)]
        return [0, 0, 0, 0] + inner + [1, 1, 1, 1]

    return {
        "scene": {"name": "large", "float_policy": "reject"},
        "surfaces": {
            "big": {
                "type": "bspline",
                "knots_u": knots(nu),
                "knots_v": knots(nv),
                "control_net": {"generator": "grid", "size": [nu, nv], "z": "x*(1-x)*y*(1-y)*4 + x*y/8"},
            }
        },
        "curves": {"trim": {"type": "bezier", "control_points": [["3/10", "2/5"], ["2/5", "3/5"], ["1/2", "2/5"], ["3/5", "1/2"]]}},
        "products": [{"kind": "image_curve", "name": "trim_image", "surface": "big", "curve": "trim"}],
    }


def run_planned(scene_dict: dict):
    from exactcagd.scenes.runner import Runner
    from exactcagd.scenes.spec import parse_scene

    with tempfile.TemporaryDirectory() as tmp:
        runner = Runner(parse_scene(scene_dict), tmp, use_cache=False)
        return runner.run(progress=lambda line: None).results["trim_image"]


def run_eager(scene_dict: dict):
    from exactcagd.composition import compose_spline
    from exactcagd.scenes.runner import Runner
    from exactcagd.scenes.spec import parse_scene

    with tempfile.TemporaryDirectory() as tmp:
        runner = Runner(parse_scene(scene_dict), tmp, use_cache=False)
        surface, curve = runner.objects["big"], runner.objects["trim"]
        patches = surface.to_bezier_patches()  # everything, by knot insertion
        result = compose_spline(surface, curve)
        for piece in result.pieces:  # same patches as the lazy extraction
            assert patches[piece.patch][1] == surface.bezier_patch(*piece.patch)[1]
        return result, len(patches)


def main(quick: bool = False) -> None:
    sizes = [(37, 19)] if quick else [(37, 19), (145, 55)]
    rows = []
    for nu, nv in sizes:
        scene = large_scene(nu, nv)
        planned = run_planned(scene)
        eager, n_patches = run_eager(scene)
        same = [p.curve for p in planned.pieces] == [p.curve for p in eager.pieces]
        t_plan = measure(lambda: run_planned(scene), repeat=3, memory=True)
        t_eager = measure(lambda: run_eager(scene), repeat=1 if nu > 100 else 3, memory=True)
        rows.append(
            [
                f"{nu} x {nv}",
                n_patches,
                len(planned.pieces),
                t_plan.fmt(),
                t_eager.fmt(),
                f"{t_eager.median / t_plan.median:.1f}x",
                f"{t_plan.peak_bytes / 2**20:.1f} MiB",
                f"{t_eager.peak_bytes / 2**20:.1f} MiB",
                "yes" if same else "NO",
            ]
        )
    body = (
        "Planned run (only crossed patches, by blossoming) versus eager run (all patches by knot\n"
        "insertion, then the same composition). Times: median (min-max); memory: tracemalloc peak.\n\n"
        + markdown_table(
            ["net", "patches", "pieces", "planned", "eager", "eager/planned", "planned peak", "eager peak", "same pieces"],
            rows,
        )
    )
    print(write_result("scenes", "Lazy planner on a large NURBS scene", body).read_text())


if __name__ == "__main__":
    main(quick=parse_quick(__doc__.splitlines()[0]))
