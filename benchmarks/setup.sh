#!/usr/bin/env bash
# Create the benchmark's own environment, beside the project's: kinematika (editable) and the
# peers it is compared with: pylinkage (with numba, and run again with numba disabled) and
# `mechanism`. Usage: bash benchmarks/setup.sh   (then: .venv-bench/bin/python benchmarks/run.py)
set -euo pipefail
cd "$(dirname "$0")/.."
python3 -m venv .venv-bench
.venv-bench/bin/pip install --quiet --upgrade pip
.venv-bench/bin/pip install --quiet -e '.[explore]' pylinkage numba mechanism
.venv-bench/bin/python -c "import kinematika, pylinkage, numba, mechanism; print('benchmark environment ready: pylinkage', pylinkage.__version__, 'numba', numba.__version__)"
