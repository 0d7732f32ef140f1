"""Shared fixtures: the real ``lowdisc`` binary for comparisons with the CLI."""

from __future__ import annotations

import os
import subprocess
from pathlib import Path

import pytest

ROOT = Path(__file__).resolve().parents[2]


@pytest.fixture(scope="session")
def lowdisc_bin() -> Path:
    """The CLI binary: $LOWDISC_BIN, else target/{debug,release}/lowdisc,
    else built with cargo (the test fails if that fails)."""
    given = os.environ.get("LOWDISC_BIN")
    if given:
        return Path(given)
    for profile in ("debug", "release"):
        path = ROOT / "target" / profile / "lowdisc"
        if path.exists():
            return path
    subprocess.run(["cargo", "build", "-p", "lowdisc-cli"], cwd=ROOT, check=True)
    return ROOT / "target" / "debug" / "lowdisc"
