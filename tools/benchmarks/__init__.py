"""Benchmarks of linecontact and of its 3D BEM (tools/benchmarks/README.md)."""


def report(text, save=None):
    """Print a benchmark's record and, given a path `save`, append it to that file."""
    print(text)
    if save:
        with open(save, "a", encoding="utf-8") as fh:
            fh.write(text + "\n")
