"""Regenerate the computed tables in tables/ (the only writer of those files).

Subcommands, each with its own options (``--help``); every study runs its tasks through
tools.studies.runner (a local Dask cluster, or ``--scheduler ADDRESS``; checkpoints and
``--resume``) and writes headers with tools.studies.runner.table_meta:

``universal``
    The universal curve Psi(d~), Phi (docs/theory.md, section 'Self-similarity') on
    adapted grids: tables/universal_curve.csv (tools.studies.universal_study).
``paper``
    The paper's study (Li & Popov 2017, section 3): BEM sweeps per L/R, fitted alpha,
    beta: tables/lipopov_regenerated.csv and the raw curves (tools.studies.paper_study).
``roller``
    Profiled and tilted rollers, runtime and ISO 16281 slicing against the 3D BEM:
    tables/roller_accuracy.csv (tools.studies.roller_study).
``stress``
    Subsurface stresses of the runtime slices against the 3D field below the 3D BEM
    pressure: tables/stress_accuracy.csv (tools.studies.stress_study).
``tangential``
    Tangential stiffness and partial slip of the finite cylinder:
    tables/tangential_cylinder.csv (tools.studies.tangential_study).
``tangential-profiles``
    Tangential stiffness by direction of profiled rollers, 3D BEM against the
    equivalent ellipse's Mindlin ratio: tables/tangential_profiles.csv
    (tools.studies.tangential_profile_study).
``adhesion``
    Pull-off force of the finite cylinder with JKR adhesion, adhesive BEM against the
    MDR's rule of Hess: tables/adhesion_cylinder.csv (tools.studies.adhesion_study).
``adhesion-long``
    Pull-off of long rollers below that table (s = b_c/L down to 1e-3): an end model
    calibrated on the BEM and checked by BEM runs below the table:
    tables/adhesion_long_roller.csv (tools.studies.adhesion_long_study).
``population``
    Drawn rollers of cylindrical, needle and cam-follower bearings at 2-50 % of their
    ISO 281 ratings: does each stated error of the runtime bound its difference to the
    3D BEM? tables/population_check.csv (tools.studies.population_study).
``bearing``
    Cylindrical roller bearings of the NU 2.. series, universal curve against the ISO
    spring law: tables/bearing_stiffness.csv (tools.studies.bearing_study).

Run from the repository root, e.g.::

    python -m tools.build_tables universal
    python -m tools.build_tables paper --l-over-r 5 --n 128 --out /tmp/check
    python -m tools.build_tables universal --scheduler tcp://HOST:8786
"""
from __future__ import annotations

import argparse
import importlib
import sys

SUBCOMMANDS = {
    "universal": "tools.studies.universal_study",
    "paper": "tools.studies.paper_study",
    "roller": "tools.studies.roller_study",
    "tangential": "tools.studies.tangential_study",
    "tangential-profiles": "tools.studies.tangential_profile_study",
    "stress": "tools.studies.stress_study",
    "accuracy": "tools.studies.accuracy",
    "adhesion": "tools.studies.adhesion_study",
    "adhesion-long": "tools.studies.adhesion_long_study",
    "bearing": "tools.studies.bearing_study",
    "population": "tools.studies.population_study",
}


#: runner options that change where and how a study runs, never its table: left out of
#: the table's ``generated_by`` (the command that regenerates it), with their values
_RUN_ONLY = {"--checkpoint": 1, "--scheduler": 1, "--workers": 1, "--connect-timeout": 1,
             "--resume": 0, "--no-progress": 0, "--out": 1}


def regenerating_command(argv):
    """The command line that regenerates a table: `argv` without the runner options of
    _RUN_ONLY (a checkpoint folder, a scheduler's address, the worker count, the
    output folder: where and how it ran, not what it computed).

    Examples
    --------
    >>> regenerating_command(["stress", "--n-x", "64", "--checkpoint", "/tmp/c",
    ...                       "--resume", "--workers=1"])
    'python -m tools.build_tables stress --n-x 64'
    """
    out, skip = [], 0
    for a in argv:
        if skip:
            skip -= 1
            continue
        name = a.split("=", 1)[0]
        if name in _RUN_ONLY:
            skip = _RUN_ONLY[name] if "=" not in a else 0
            continue
        out.append(a)
    return "python -m tools.build_tables " + " ".join(out)


def main(argv=None):
    argv = sys.argv[1:] if argv is None else list(argv)
    if not argv or argv[0] not in SUBCOMMANDS:
        names = ", ".join(SUBCOMMANDS)
        print(f"usage: python -m tools.build_tables {{{names}}} [options]\n{__doc__}",
              file=sys.stderr)
        return 2
    module = importlib.import_module(SUBCOMMANDS[argv[0]])
    parser = argparse.ArgumentParser(prog=f"python -m tools.build_tables {argv[0]}",
                                     description=module.__doc__,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    module.add_arguments(parser)
    args = parser.parse_args(argv[1:])
    args.command_line = regenerating_command(argv)
    from tools.studies.runner import StudyError
    try:
        return module.run(args) or 0
    except StudyError as exc:          # one line that says what to do, no traceback
        print(f"error: {exc}", file=sys.stderr)
        return exc.exit_code


if __name__ == "__main__":
    sys.exit(main())
