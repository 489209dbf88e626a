"""The studies that regenerate tables/ (run through tools.studies.runner on Dask) and
the figures (tools/build_tables.py is their one entry point)."""
