"""The commands whose CSV batches (and DataFrames) keep the calculator's input rules:
``linecontact calc`` and every subcommand (``linecontact bearing``). The input-rule
tests (tests/test_command_input_contracts.py, tests/test_cli.py, tests/test_frame.py) are
parametrised over :data:`DOORS`: one valid case of each, the load column of each (the
column the tests vary), and how to read the load back from a result row.
"""
from __future__ import annotations

from dataclasses import dataclass, field


@dataclass(frozen=True)
class Door:
    """One command as the input-rule tests use it."""

    name: str
    #: the input columns of a valid case, the load last
    header: str
    #: the cells of that case, ``{load}`` for the load
    row: str
    #: the load column and its option
    load: str
    #: a result column that is a positive number for every computed row
    result: str
    #: close spellings of input columns: (typo, the parameter it matches)
    typos: tuple
    #: the valid case as options (the load aside)
    options: tuple = field(default=())

    @property
    def load_option(self):
        return "--" + self.load.replace("_", "-")

    @property
    def parameters(self):
        """Every input name of the command (its CSV columns)."""
        if self.name == "calc":
            from linecontact.calc.cases import BY_NAME
            return sorted(BY_NAME)
        from linecontact.calc.subcommands import SUBCOMMANDS
        mod = next(m for m in SUBCOMMANDS if m.name == self.name)
        return sorted(p.name for p in mod.parameters)

    def load_of(self, row):
        """The load [N] a computed result row (engineering units) was computed at:
        calc prints it (force_kN); a bearing's ISO 281 life is (C_r/F_r)^(10/3)
        (ISO 281:2007), so F_r = C_r L10^(-3/10) (to the CSV's 6 digits)."""
        if self.name == "calc":
            return float(row["force_kN"]) * 1e3
        return float(row["rating_kN"]) * 1e3 * float(row["life_iso281_1e6_rev"]) ** -0.3

    def frame(self, cases, **options):
        """The DataFrame door (linecontact.calc.frame)."""
        from linecontact.calc.frame import calc_frame, command_frame
        if self.name == "calc":
            return calc_frame(cases, **options)
        return command_frame(self.name, cases, **options)


CALC = Door("calc", "radius,length,modulus,poisson,load", "5mm,10mm,210GPa,0.3,{load}",
            "load", "depth_um",
            (("lode", "load"), ("raduis", "radius"), ("lenght", "length"),
             ("modulos", "modulus"), ("poison", "poisson"), ("dept", "depth")),
            ("--radius", "5mm", "--length", "10mm", "--modulus", "210GPa", "--poisson",
             "0.3"))
BEARING = Door("bearing", "rollers,pitch_diameter,roller_diameter,length,radial_load",
               "14,70mm,11mm,11mm,{load}", "radial_load", "displacement_um",
               (("radial_lode", "radial_load"), ("rolers", "rollers"),
                ("pitch_diamter", "pitch_diameter"), ("lenght", "length"),
                ("clearence", "clearance")),
               ("--rollers", "14", "--pitch-diameter", "70mm", "--roller-diameter",
                "11mm", "--length", "11mm"))

DOORS = (CALC, BEARING)
IDS = [d.name for d in DOORS]
