#!/usr/bin/env bash
# The Python package's test suite on a fresh machine (Rust + Python >= 3.9 +
# network to PyPI and crates.io): builds the CLI (for the byte-identity test
# of the batch protocol), creates a venv, builds the wheel with
# `maturin build --release` (the README's command), installs ./python with
# its dask and test extras the way a user does (`pip install`, which builds
# through maturin's PEP 517 backend), and runs pytest (the Dask tests start
# a 2-worker distributed.LocalCluster).
#
#   scripts/test_python.sh [pytest args...]
#
# Environment: PYTHON (default python3), QUADSECT_PY_VENV (default
# .venv-pytest under the repository), QUADSECT_HYPOTHESIS_EXAMPLES (default 60).
set -euo pipefail
cd "$(dirname "$0")/.."
root=$(pwd)
python=${PYTHON:-python3}
venv=${QUADSECT_PY_VENV:-$root/.venv-pytest}
step_start=$SECONDS
lap() { echo "   ($(( SECONDS - step_start )) s so far)"; }

echo "== cargo build --release --bin quadsect   (the CLI the batch tests compare with)"
cargo build --release --quiet --bin quadsect
lap

echo "== venv $venv"
if [ ! -x "$venv/bin/python" ]; then
  "$python" -m venv "$venv"
fi
"$venv/bin/python" -m pip install --quiet --upgrade pip maturin
lap

echo "== maturin build --release   (the wheel: one abi3 wheel for CPython >= 3.9)"
rm -f "$root"/target/wheels/quadsect-*.whl
(cd python && "$venv/bin/maturin" build --release --quiet)
wheel=$(ls "$root"/target/wheels/quadsect-*-cp39-abi3-*.whl)
echo "   built $(basename "$wheel")"
lap

echo "== pip install './python[dask,test,occ]'"
# --force-reinstall --no-deps first: a rebuilt wheel of the same version
# must replace the installed one; then the extras' dependencies
"$venv/bin/python" -m pip install --quiet --force-reinstall --no-deps ./python
"$venv/bin/python" -m pip install --quiet './python[dask,test,occ]'
# the quadsect.occ tests must run, not skip, here
export QUADSECT_REQUIRE_OCC=1
lap

echo "== pytest python/tests"
export QUADSECT_BIN="$root/target/release/quadsect"
cd python   # `pytest`, not `python -m pytest`: the installed package is imported
"$venv/bin/pytest" -q -p no:cacheprovider "$@"
lap
