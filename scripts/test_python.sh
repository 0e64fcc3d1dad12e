#!/usr/bin/env bash
# The Python package's test suite on a fresh machine (Rust + Python >= 3.9 +
# network to PyPI and crates.io): builds the CLI (for the byte-identity test
# of the batch protocol), creates a venv, installs ./python with its dask
# and test extras (pip builds the wheel with maturin), and runs pytest.
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

echo "== cargo build --release --bin quadsect   (the CLI the batch tests compare with)"
cargo build --release --quiet --bin quadsect

echo "== venv $venv"
if [ ! -x "$venv/bin/python" ]; then
  "$python" -m venv "$venv"
fi
"$venv/bin/python" -m pip install --quiet --upgrade pip

echo "== pip install './python[dask,test]'"
# --force-reinstall --no-deps first: a rebuilt wheel of the same version
# must replace the installed one; then the extras' dependencies
"$venv/bin/python" -m pip install --quiet --force-reinstall --no-deps ./python
"$venv/bin/python" -m pip install --quiet './python[dask,test]'

echo "== pytest python/tests"
export QUADSECT_BIN="$root/target/release/quadsect"
cd python   # `pytest`, not `python -m pytest`: the installed package is imported
"$venv/bin/pytest" -q -p no:cacheprovider "$@"
