#!/usr/bin/env bash
# Fresh-wheel job: build exactcagd's wheel from the tracked files, install it with the [plots]
# extra (as the README does) into a fresh venv (no system site-packages), and from an empty
# directory run --version, a scene, a partial proof ledger and reference data; then check that
# each command wrote only where it was told and nothing landed in site-packages, and that
# `bench` says it needs a checkout.  Prints the wheel's path on success.
# Usage: .ci/fresh_wheel.sh [extra pip arguments, e.g. -c .ci/constraints-floor.txt]
set -euo pipefail
repo="$(cd "$(dirname "$0")/.." && pwd)"
python="${PYTHON:-python3}"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT
fail() { echo "fresh-wheel: FAILED: $*" >&2; exit 1; }

# the committed tree (HEAD), as a release would be built; building in the checkout would leave build/ behind
mkdir "$work/src"
git -C "$repo" archive HEAD | tar -xf - -C "$work/src"
"$python" -m pip wheel -q --no-deps "$work/src" -w "$work/wheel"
wheel="$(ls "$work"/wheel/exactcagd-*.whl)"
# list once into a file: `unzip | grep -q` fails under pipefail when grep stops reading early (SIGPIPE)
unzip -Z1 "$wheel" > "$work/wheel.list"
grep -Eq '^(proofs|benchmarks|tests|examples)/' "$work/wheel.list" && fail "wheel ships a top-level proofs/benchmarks/tests/examples"
grep -qx 'exactcagd/py.typed' "$work/wheel.list" || fail "wheel lacks exactcagd/py.typed"
grep -q 'dist-info/licenses/LICENSE$' "$work/wheel.list" || fail "wheel lacks LICENSE"

"$python" -m venv "$work/venv"
"$work/venv/bin/python" -m pip install -q "$@" "exactcagd[plots] @ file://$wheel"
site="$("$work/venv/bin/python" -c 'import sysconfig; print(sysconfig.get_paths()["purelib"])')"
listing() { (cd "$site" && find . -path '*/__pycache__' -prune -o -print | sort); }
listing > "$work/site.before"

mkdir "$work/empty"
cd "$work/empty"
export MPLCONFIGDIR="$work/mplconfig"   # matplotlib's font cache: not in $HOME, not in site-packages
bin="$work/venv/bin"
version="$("$bin/python" -c 'from exactcagd._version import __version__; print(__version__)')"
[ "$("$bin/exactcagd" --version)" = "exactcagd $version" ] || fail "--version"
"$bin/exactcagd" run "$repo/examples/scenes/hill_trim.toml" --out out > run.log 2>&1 || { cat run.log; fail "run"; }
[ -f out/hill_trim/summary.json ] && [ -f out/hill_trim/overview.png ] || fail "run wrote no summary.json/overview.png"
"$bin/exactcagd" verify --fast --doc lasser --out ledger > verify.log 2>&1 || { tail -20 verify.log; fail "verify"; }
[ "$(ls ledger)" = "$(printf 'LEDGER-lasser-fast.md\nledger-lasser-fast.json')" ] || fail "verify wrote $(ls ledger)"
"$bin/exactcagd" refdata compose --count 3 --out r.jsonl > refdata.log 2>&1 || { cat refdata.log; fail "refdata"; }
[ "$(wc -l < r.jsonl)" -eq 3 ] || fail "refdata wrote $(wc -l < r.jsonl) records"
set +e
"$bin/exactcagd" bench --quick > bench.log 2>&1
rc=$?
set -e
[ "$rc" -eq 2 ] && grep -q "needs a repository checkout" bench.log || { cat bench.log; fail "bench (rc $rc)"; }
rm run.log verify.log refdata.log bench.log
[ "$(ls -A | tr '\n' ' ')" = "ledger out r.jsonl " ] || fail "the empty directory now holds: $(ls -A)"
listing > "$work/site.after"
diff "$work/site.before" "$work/site.after" || fail "the commands wrote into site-packages (diff above)"
echo "fresh-wheel: ok ($(basename "$wheel"))"
