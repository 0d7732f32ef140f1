"""scipy's own tests of ``scipy.stats.qmc`` (``scipy/stats/tests/test_qmc.py``
of the installed scipy), run against :mod:`lowdisc.qmc`.

The test module is read from the installed scipy and executed here with its
``qmc`` being ``lowdisc.qmc`` (so ``qmc.Sobol``, ``qmc.Halton``,
``qmc.discrepancy``, ``qmc.geometric_discrepancy`` are lowdisc's; the names
lowdisc re-exports stay scipy's) and ``update_discrepancy`` lowdisc's. Every
test then runs as if it were in this file. The tests listed in
``BY_DESIGN`` are expected to fail (strict: if one passes, this suite
fails, so the list stays true); the reasons are documented in
``docs/guide/python.md``.
"""

from __future__ import annotations

from pathlib import Path

import pytest

scipy_stats = pytest.importorskip("scipy.stats")

SOURCE = Path(scipy_stats.__file__).parent / "tests" / "test_qmc.py"

#: Tests that fail by design, with the reason (test id suffix -> reason).
BY_DESIGN = {
    "TestSobol::test_sample[Scrambled]":
        "scipy's reference values of its own LMS scramble; lowdisc scrambles with Owen's",
    "TestHalton::test_sample[Scrambled]":
        "scipy's reference values of its own digit permutations; lowdisc scrambles with Owen's",
    "TestHalton::test_workers":
        "compares with scipy's scrambled reference values (as test_sample[Scrambled])",
    "TestNormalQMC::test_NormalQMCSeeded":
        "reference values of normal draws from scipy's scrambled Sobol (its second half "
        "passes lowdisc's Sobol as the engine)",
}

# The import lines replaced, so that the module's `qmc` and
# `update_discrepancy` are lowdisc's.
QMC_IMPORT = "from scipy.stats import qmc\n"
PRIVATE_IMPORT = "from scipy.stats._qmc import ("


def _patched_source() -> str:
    if not SOURCE.exists():
        pytest.fail(f"scipy's test_qmc.py is not installed ({SOURCE}): this scipy was built "
                    "without its tests; install a scipy wheel from PyPI, which includes them",
                    pytrace=False)
    text = SOURCE.read_text()
    if QMC_IMPORT not in text or PRIVATE_IMPORT not in text:
        pytest.fail(f"{SOURCE} no longer imports qmc as this file expects", pytrace=False)
    text = text.replace(QMC_IMPORT, "from lowdisc import qmc\n", 1)
    # Appended after the module's imports: lowdisc's update_discrepancy
    # replaces the private scipy import of the same name.
    first_class = text.index("\nclass ")
    return (text[:first_class] + "\nfrom lowdisc.qmc import update_discrepancy  # noqa\n"
            + text[first_class:])


exec(compile(_patched_source(), str(SOURCE), "exec"), globals())  # noqa: S102

