"""``python -m linecontact``: the same as the ``linecontact`` console script."""

if __name__ == "__main__":  # guarded: pytest --doctest-modules imports this module
    import sys

    from linecontact.calc.cli import main

    sys.exit(main())
