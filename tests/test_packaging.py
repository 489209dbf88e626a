"""pyproject.toml installs every sub-package of linecontact.

Fact checked: each folder of linecontact/ with an __init__.py is named in
[tool.setuptools] packages, so that a non-editable install (README's `pip install .`,
a dask worker without the repository) has the same modules as the checkout.
"""
from __future__ import annotations

import re
from pathlib import Path

ROOT = Path(__file__).resolve().parent.parent


def test_every_subpackage_is_installed():
    text = (ROOT / "pyproject.toml").read_text()
    listed = set(re.findall(r'"(linecontact[\w.]*)"',
                            re.search(r"packages = \[([^\]]*)\]", text).group(1)))
    found = {".".join(p.parent.relative_to(ROOT).parts)
             for p in (ROOT / "linecontact").rglob("__init__.py")}
    missing = sorted(found - listed)
    assert not missing, f"pyproject.toml [tool.setuptools] packages lacks {missing}"
