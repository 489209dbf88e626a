"""Benchmarks of linecontact and of its 3D BEM: ``python -m tools.benchmarks``
(tools/benchmarks/README.md)."""
