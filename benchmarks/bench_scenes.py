"""Scenes: the lazy planner on a large scene, and a rerun from the cache (issues: scenes, 18).

A bicubic B-spline surface with 145 x 55 control points (142 x 52 = 7384 Bézier patches)
and one cubic trim curve.  The planned run extracts only the patches the curve crosses
(by blossoming) and composes the pieces; the eager run extracts every patch by knot
insertion first, as a non-lazy pipeline would, then composes.  Both must give the same
exact pieces.  Time and peak memory (tracemalloc) are compared in the same process.

A rerun of the README's scene (``examples/scenes/hill_trim.toml``, pictures included)
loads every product and picture from the content cache; issue 18 asks that it cost at most
0.1x of the first run.  Both are timed twice: the in-process runner (``Runner.run``) and
the command a user types (``exactcagd run ... --out``, wall time including the
interpreter start and imports), each first run into a fresh output folder.

    python -m benchmarks.bench_scenes [--quick]
"""

from __future__ import annotations

import subprocess
import sys
import tempfile
import time
from pathlib import Path

from ._common import fmt_bytes, markdown_table, measure, parse_quick, write_result


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


EXAMPLE_SCENE = Path(__file__).resolve().parent.parent / "examples" / "scenes" / "hill_trim.toml"


def run_in_process(out_dir, traced: bool = False) -> float | int:
    """Seconds of one ``Runner.run`` of the example scene into ``out_dir``; with ``traced``, its
    tracemalloc peak in bytes instead (tracing slows the run, so the two are separate runs)."""
    import tracemalloc

    from exactcagd.scenes.runner import Runner
    from exactcagd.scenes.spec import load_scene

    if traced:
        tracemalloc.start()
    start = time.perf_counter()
    Runner(load_scene(EXAMPLE_SCENE), out_dir).run(progress=lambda line: None)
    seconds = time.perf_counter() - start
    if not traced:
        return seconds
    peak = tracemalloc.get_traced_memory()[1]
    tracemalloc.stop()
    return peak


#: the command, reporting its peak resident memory: VmHWM of /proc/self/status belongs to the
#: process image since exec (ru_maxrss would carry over the forking benchmark's own peak)
_COMMAND = (
    "import atexit, sys\n"
    "def report():\n"
    "    for line in open('/proc/self/status'):\n"
    "        if line.startswith('VmHWM:'):\n"
    "            print('VMHWM', line.split()[1], file=sys.stderr)\n"
    "atexit.register(report)\n"
    "from exactcagd.cli import main\n"
    "sys.exit(main(sys.argv[1:]))\n"
)


def run_command(out_dir, traced: bool = False) -> float | int:
    """Wall seconds of ``exactcagd run <scene> --out out_dir`` (the console script's entry in a
    fresh interpreter); with ``traced``, its peak resident memory in bytes instead."""
    start = time.perf_counter()
    done = subprocess.run([sys.executable, "-c", _COMMAND, "run", str(EXAMPLE_SCENE), "--out", str(out_dir)],
                          check=True, capture_output=True, text=True)
    seconds = time.perf_counter() - start
    return int(done.stderr.rsplit("VMHWM", 1)[1].split()[0]) * 1024 if traced else seconds  # kB


def cache_rows(repeat: int) -> list:
    """First run vs rerun from the cache, in-process and as a command: minimum times of ``repeat``
    fresh folders, then one more fresh folder for the peak memory of each (tracemalloc in-process,
    peak resident as a command)."""
    rows = []
    for label, runner in (("in-process `Runner.run` (tracemalloc peak)", run_in_process),
                          ("command `exactcagd run` (peak resident)", run_command)):
        first, rerun = [], []
        for _ in range(repeat):
            with tempfile.TemporaryDirectory() as tmp:
                first.append(runner(tmp))
                rerun.append(runner(tmp))
        with tempfile.TemporaryDirectory() as tmp:
            peaks = runner(tmp, traced=True), runner(tmp, traced=True)
        ratio = min(rerun) / min(first)
        rows.append([label, f"{min(first):.3f} s", f"{min(rerun):.3f} s", f"{ratio:.3f}x", "yes" if ratio <= 0.1 else "no",
                     fmt_bytes(peaks[0]), fmt_bytes(peaks[1])])
    return rows


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
    body += (
        "\n\n## Rerun from the cache (issue 18 goal: <= 0.1x of the first run)\n\n"
        f"The README's scene `{EXAMPLE_SCENE.relative_to(EXAMPLE_SCENE.parents[2])}` (every product and its pictures): "
        "first run into a fresh output folder, then the same run again (every product and picture loaded from "
        "the content cache and copied into place).  Minimum of 3 fresh folders each.\n\n"
        + markdown_table(["how", "first run", "rerun from the cache", "rerun / first", "goal <= 0.1x met", "peak memory, first",
                          "peak memory, rerun"], cache_rows(3))
    )
    print(write_result("scenes", "Scenes: lazy planner, rerun from the cache", body).read_text())


if __name__ == "__main__":
    main(quick=parse_quick(__doc__.splitlines()[0]))
