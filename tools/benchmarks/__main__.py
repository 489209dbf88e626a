"""``python -m tools.benchmarks``: the benchmark runner (tools/benchmarks/runner.py)."""
import sys

from tools.benchmarks.runner import main

sys.exit(main())
