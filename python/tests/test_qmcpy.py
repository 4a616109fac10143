"""The QMCPy adapter (skipped when QMCPy is not installed)."""

import numpy as np
import pytest
from numpy.testing import assert_array_equal

qmcpy = pytest.importorskip("qmcpy")

import qmckit  # noqa: E402
from qmckit.qmcpy import QMCKit  # noqa: E402


def test_shapes_and_random_access():
    dd = QMCKit(3, replications=4, seed=7)
    x = dd(n_min=0, n_max=16)
    assert x.shape == (4, 16, 3)
    assert_array_equal(dd(n_min=8, n_max=16), x[:, 8:])
    one = QMCKit(3, seed=7)
    assert one(8).shape == (8, 3)
    assert not np.array_equal(x[0], x[1])


def test_dimension_subset():
    dd = QMCKit([0, 4], seed=1, engine="Halton", randomize=False)
    full = qmckit.Halton(5, scramble=False).random(10)
    assert_array_equal(dd(10), full[:, [0, 4]])


@pytest.mark.parametrize("engine, kwargs", [("Sobol", {}), ("Sobol", {"randomizer": "lms"}),
                                            ("Halton", {}), ("Lattice", {}), ("Faure", {})])
def test_keister_integral(engine, kwargs):
    """QMCPy's Keister example with QMCPy's replicated Student-t stopping rule; the
    answer agrees with QMCPy's own digital net to the tolerance."""
    ref_k = qmcpy.Keister(qmcpy.DigitalNetB2(3, seed=7, replications=16))
    ref, _ = qmcpy.CubQMCRepStudentT(ref_k, abs_tol=1e-3, rel_tol=0).integrate()
    k = qmcpy.Keister(QMCKit(3, replications=16, seed=7, engine=engine, **kwargs))
    sol, data = qmcpy.CubQMCRepStudentT(k, abs_tol=1e-3, rel_tol=0).integrate()
    assert abs(float(sol) - float(ref)) < 2e-3


def test_spawn():
    dd = QMCKit(2, replications=3, seed=11)
    kids = dd.spawn(2, dimensions=[2, 4])
    assert [k.d for k in kids] == [2, 4]
    assert kids[1](4).shape == (3, 4, 4)
