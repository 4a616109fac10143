"""``qmckit.discrepancy`` against SciPy's ``qmc.discrepancy``.

The cases are SciPy's own: SciPy's discrepancy tests (read from the installed
``scipy/stats/tests/test_qmc.py`` and run as they are) call ``qmc.discrepancy``, which
is replaced here by a function that computes both SciPy's value and qmckit's, checks that
they agree to 1e-12 relative (or raise the same error), and returns qmckit's, so SciPy's
own assertions then check qmckit's values too.
"""

import numpy as np
import pytest
from numpy.testing import assert_allclose
from scipy.stats import qmc
from scipy.stats.tests import test_qmc as scipy_tests

import qmckit

RTOL = 1e-12
SCIPY_DISCREPANCY = qmc.discrepancy


class Comparing:
    """``qmc.discrepancy``'s stand-in: qmckit's value, checked against SciPy's."""

    def __init__(self):
        self.calls = 0

    def __call__(self, sample, **kwargs):
        try:
            expected = SCIPY_DISCREPANCY(sample, **kwargs)
        except Exception as e:  # SciPy refuses: qmckit must refuse the same way
            with pytest.raises(type(e)) as info:
                qmckit.discrepancy(sample, **kwargs)
            assert str(info.value) == str(e)
            raise
        got = qmckit.discrepancy(sample, **kwargs)
        assert_allclose(got, expected, rtol=RTOL, atol=0)
        self.calls += 1
        return got


SCIPY_CASES = [
    "test_discrepancy",
    "test_discrepancy_errors",
    "test_discrepancy_parallel",
    "test_discrepancy_alternative_implementation",
    "test_update_discrepancy",
    "test_perm_discrepancy",
]


@pytest.mark.parametrize("name", SCIPY_CASES)
def test_scipy_case(name, monkeypatch):
    comparing = Comparing()
    monkeypatch.setattr(qmc, "discrepancy", comparing)
    case = getattr(scipy_tests.TestUtils(), name)
    if "monkeypatch" in case.__code__.co_varnames[: case.__code__.co_argcount]:
        case(monkeypatch)
    else:
        case()
    if name != "test_discrepancy_errors":
        assert comparing.calls > 0


def _reference(x, method, iterative):
    """The discrepancy in extended precision (numpy.longdouble: 64-bit significands on
    x86-64), by the formulas SciPy documents."""
    x = np.asarray(x, dtype=np.longdouble)
    n, d = x.shape
    m = n + 1 if iterative else n
    xi, xj = x[:, None, :], x[None, :, :]
    one = np.longdouble(1)
    if method == "CD":
        a = np.abs(x - one / 2)
        s1 = np.sum(np.prod(1 + a / 2 - a * a / 2, axis=1))
        ai, aj = a[:, None, :], a[None, :, :]
        s2 = np.sum(np.prod(1 + ai / 2 + aj / 2 - np.abs(xi - xj) / 2, axis=2))
        return (np.longdouble(13) / 12) ** d - 2 * s1 / m + s2 / m**2
    if method == "WD":
        t = np.abs(xi - xj)
        s2 = np.sum(np.prod(np.longdouble(3) / 2 - t * (1 - t), axis=2))
        return -((np.longdouble(4) / 3) ** d) + s2 / m**2
    if method == "MD":
        a = np.abs(x - one / 2)
        s1 = np.sum(np.prod(np.longdouble(5) / 3 - a / 4 - a * a / 4, axis=1))
        ai, aj = a[:, None, :], a[None, :, :]
        t = np.abs(xi - xj)
        s2 = np.sum(np.prod(np.longdouble(15) / 8 - ai / 4 - aj / 4 - 3 * t / 4 + t * t / 2, axis=2))
        return (np.longdouble(19) / 12) ** d - 2 * s1 / m + s2 / m**2
    s1 = np.sum(np.prod(1 - x * x, axis=1))
    s2 = np.sum(np.prod(1 - np.maximum(xi, xj), axis=2))
    return np.sqrt(np.longdouble(3) ** -d - np.longdouble(2) ** (1 - d) * s1 / m + s2 / m**2)


@pytest.mark.parametrize("method", ["CD", "WD", "MD", "L2-star"])
@pytest.mark.parametrize("shape", [(1, 1), (7, 3), (200, 5), (512, 8), (64, 40)])
def test_random_samples(method, shape):
    """Against an extended-precision reference: qmckit within 1e-12 relative (measured:
    at most 5e-13, the mixture discrepancy of 512 points in 8D); SciPy's
    plain double sums within 1e-10 (on these larger samples SciPy's own rounding, up to
    2e-11 relative, exceeds 1e-12)."""
    x = np.random.default_rng(sum(shape)).random(shape)
    for iterative in (False, True):
        ref = float(_reference(x, method, iterative))
        got = qmckit.discrepancy(x, method=method, iterative=iterative)
        scipy_value = SCIPY_DISCREPANCY(x, method=method, iterative=iterative)
        assert_allclose(got, ref, rtol=1e-12)
        assert_allclose(scipy_value, ref, rtol=1e-10)


def test_update_discrepancy_from_iterative():
    """SciPy's documented use of iterative=True: update_discrepancy from it."""
    space = np.array([[1, 3], [2, 6], [3, 2], [4, 5], [5, 1], [6, 4]])
    space = (2.0 * space - 1.0) / 12.0
    init = qmckit.discrepancy(space[:-1], iterative=True)
    updated = qmc.update_discrepancy(space[-1], space[:-1], init)
    assert_allclose(updated, qmckit.discrepancy(space), rtol=1e-12)


@pytest.mark.parametrize("method", ["CD", "WD", "MD", "L2-star"])
def test_workers_do_not_change_the_value(method):
    x = qmckit.Sobol(6, rng=1).random(2048)
    one = qmckit.discrepancy(x, method=method, workers=1)
    assert qmckit.discrepancy(x, method=method, workers=2) == one
    assert qmckit.discrepancy(x, method=method, workers=-1) == one


def test_accepts_non_contiguous_and_lists():
    x = np.random.default_rng(0).random((50, 6))
    assert qmckit.discrepancy(x[:, ::2]) == qmckit.discrepancy(np.ascontiguousarray(x[:, ::2]))
    assert qmckit.discrepancy(x.tolist()) == qmckit.discrepancy(x)
