"""The seeds' own tables in the one benchmark run: Yang et al. (2012) Tables 1-4 analogues.

Delegates to ``examples/yang_tables.py`` (stand-in models, the three methods and the exact
composition at eps_D = 1e-1 ... 1e-5, the paper's printed figures alongside).  Full mode
rewrites ``benchmarks/results/full/yang_tables.md`` (about 6 minutes on 2 cores); quick mode
runs two models at two tolerances without pictures (about 3 minutes) and writes
``benchmarks/results/yang_tables.md`` (see ``_common.results_dir``).
"""

from __future__ import annotations

import importlib.util
import shutil
from pathlib import Path

from benchmarks._common import parse_quick, results_dir

SCRIPT = Path(__file__).resolve().parent.parent / "examples" / "yang_tables.py"


def main(quick: bool = False) -> None:
    if not SCRIPT.exists():
        raise FileNotFoundError(f"{SCRIPT} is part of the repository checkout: run the benchmarks from a clone")
    spec = importlib.util.spec_from_file_location("yang_tables", SCRIPT)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    if quick:
        module.main(["--quick", "--no-pictures", "--no-commit-copy"])
        shutil.copyfile(module.OUT / "tables.md", results_dir(quick=True) / "yang_tables.md")
    else:
        module.main([])  # writes results/full/yang_tables.md itself


if __name__ == "__main__":
    main(parse_quick(__doc__.splitlines()[0]))
