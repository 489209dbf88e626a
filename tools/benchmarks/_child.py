"""One benchmark in this process, its figures as one JSON line (runner.py runs it with
the checkout under test as working directory and first on the path)."""
import importlib.util
import json
import os
import sys

name, repeat = sys.argv[1], int(sys.argv[2])
spec = importlib.util.spec_from_file_location(
    "lc_bench_suite", os.path.join(os.environ["LC_BENCH_HOME"], "suite.py"))
suite = importlib.util.module_from_spec(spec)
spec.loader.exec_module(suite)
func = suite.BENCHMARKS[name][0]
figures = func(repeat)
print(json.dumps(None if figures is None else
                 {k: [float(v), u] for k, (v, u) in figures.items()}))
