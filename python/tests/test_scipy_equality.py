"""Points equal to SciPy's, to the last bit: unscrambled Sobol' and Halton, and the
scrambles drawn as SciPy draws them (Sobol' LMS + shift, Halton ``randomizer="scipy-perm"``)."""

import warnings

import numpy as np
import pytest
from numpy.testing import assert_array_equal
from scipy.stats import qmc
from scipy.stats.tests import test_qmc as scipy_tests

import qmckit
from conftest import ALL_ENGINES

DIMS = [1, 2, 3, 8, 100, 1111]


def _pair(ours, theirs, n, *, skip=0, chunks=(None,)):
    """Draw ``n`` points after skipping ``skip`` from both engines (ours in ``chunks``)."""
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", UserWarning)
        if skip:
            ours.fast_forward(skip)
            theirs.fast_forward(skip)
        a = np.concatenate([ours.random(c) for c in chunks]) if chunks[0] else ours.random(n)
        b = theirs.random(n)
    return a, b


@pytest.mark.parametrize("d", DIMS)
def test_sobol_unscrambled_equals_scipy(d):
    a, b = _pair(qmckit.Sobol(d, scramble=False), qmc.Sobol(d, scramble=False), 1024)
    assert_array_equal(a, b)
    a, b = _pair(
        qmckit.Sobol(d, scramble=False), qmc.Sobol(d, scramble=False), 300,
        skip=77, chunks=(100, 1, 199),
    )
    assert_array_equal(a, b)


@pytest.mark.parametrize("d", DIMS)
def test_halton_unscrambled_equals_scipy(d):
    a, b = _pair(qmckit.Halton(d, scramble=False), qmc.Halton(d, scramble=False), 1000)
    assert_array_equal(a, b)
    a, b = _pair(
        qmckit.Halton(d, scramble=False), qmc.Halton(d, scramble=False), 300,
        skip=123_456 if d <= 100 else 4321, chunks=(100, 1, 199),
    )
    assert_array_equal(a, b)


def test_halton_ten_thousand_dims_equal_scipy():
    a, b = _pair(qmckit.Halton(10_000, scramble=False), qmc.Halton(10_000, scramble=False), 16,
                 skip=1000)
    assert_array_equal(a, b)


def test_halton_high_indices_equal_scipy():
    """The last 64 indices below 2^32 (SciPy's fast_forward would draw 2^32 points, so
    its reference is its van der Corput function at that start index)."""
    from scipy.stats._qmc import n_primes, van_der_corput

    start = 2**32 - 64
    a = qmckit.Halton(5, scramble=False).fast_forward(start).random(64)
    b = np.stack([van_der_corput(64, p, start_index=start) for p in n_primes(5)], axis=1)
    assert_array_equal(a, b)


@pytest.mark.parametrize("bits", [2, 3, 10, 30, 32])
def test_sobol_bits_equal_scipy(bits):
    # Three dimensions: SciPy 1.17 mis-initializes the direction numbers of dimensions
    # whose primitive polynomial has a degree above `bits` (e.g. d=4 with bits=2: an
    # ignored exception in _initialize_v, and dimension 0 is no longer van der Corput).
    n = min(2**bits, 4096)
    a, b = _pair(qmckit.Sobol(3, scramble=False, bits=bits), qmc.Sobol(3, scramble=False, bits=bits), n)
    assert_array_equal(a, b)
    a, b = _pair(qmckit.Sobol(3, bits=bits, randomizer="lms", rng=5), qmc.Sobol(3, bits=bits, rng=5), n)
    assert_array_equal(a, b)


def test_sobol_few_bits_high_dims():
    """Where SciPy's small-`bits` initialization fails, qmckit's points are the first
    points of the sequence: every dimension starts 0, 1/2, then 1/4 or 3/4."""
    x = qmckit.Sobol(8, scramble=False, bits=2).random(4)
    assert_array_equal(x[0], 0)
    assert_array_equal(x[1], 0.5)
    assert set(x[2:].ravel()) <= {0.25, 0.75}
    assert_array_equal(x, qmckit.Sobol(8, scramble=False).random(4))


@pytest.mark.parametrize("d", DIMS)
@pytest.mark.parametrize("seed", [0, 170382760648021597650530316304495310428])
def test_sobol_lms_equals_scipy(d, seed):
    a, b = _pair(qmckit.Sobol(d, randomizer="lms", rng=seed), qmc.Sobol(d, rng=seed), 512)
    assert_array_equal(a, b)
    a, b = _pair(
        qmckit.Sobol(d, randomizer="lms", rng=seed), qmc.Sobol(d, rng=seed), 256,
        skip=1000, chunks=(5, 251),
    )
    assert_array_equal(a, b)


@pytest.mark.parametrize("d", [1, 2, 3, 8, 100])
@pytest.mark.parametrize("seed", [0, 170382760648021597650530316304495310428])
def test_halton_scipy_perm_equals_scipy(d, seed):
    def ours():
        return qmckit.Halton(d, rng=seed, randomizer="scipy-perm")

    a, b = _pair(ours(), qmc.Halton(d, rng=seed), 500)
    assert_array_equal(a, b)
    a, b = _pair(ours(), qmc.Halton(d, rng=seed), 200,
                 skip=9999, chunks=(3, 197))
    assert_array_equal(a, b)


def test_seed_keyword_as_scipy():
    """``seed=`` (SciPy's transition rules): a RandomState, and a Generator."""
    for seed in (np.random.RandomState(3), np.random.default_rng(3)):
        s2 = type(seed)(3) if isinstance(seed, np.random.RandomState) else np.random.default_rng(3)
        a = qmckit.Sobol(3, randomizer="lms", seed=seed).random(8)
        b = qmc.Sobol(3, seed=s2).random(8)
        assert_array_equal(a, b)


def test_integers_equal_scipy():
    a = qmckit.Halton(3, rng=4, randomizer="scipy-perm").integers([0, 5, -3], u_bounds=[10, 9, 3], n=100, workers=2)
    b = qmc.Halton(3, rng=4).integers([0, 5, -3], u_bounds=[10, 9, 3], n=100)
    assert_array_equal(a, b)


# SciPy's own Sobol'-specific tests, on qmckit.Sobol.

def test_sobol_warning():
    with pytest.warns(UserWarning, match=r"The balance properties of Sobol' points"):
        qmckit.Sobol(1).random(10)


def test_sobol_random_base2():
    ref = scipy_tests.TestSobol.unscramble_nd
    engine = qmckit.Sobol(2, scramble=False)
    assert_array_equal(ref[:4], engine.random_base2(2))
    assert_array_equal(ref[4:8], engine.random_base2(2))
    with pytest.raises(ValueError, match=r"The balance properties of Sobol' points"):
        engine.random_base2(2)


def test_sobol_raise():
    with pytest.raises(ValueError, match=r"Maximum supported dimensionality"):
        qmckit.Sobol(qmckit.Sobol.MAXDIM + 1)
    assert qmckit.Sobol.MAXDIM == qmc.Sobol.MAXDIM == 21201
    with pytest.raises(ValueError, match=r"Maximum supported 'bits' is 32"):
        qmckit.Sobol(1, bits=33)
    with pytest.raises(ValueError, match=r"Maximum supported 'bits' is 32"):
        qmckit.Sobol(1, bits=64)


def test_sobol_high_dim():
    from collections import Counter

    engine = qmckit.Sobol(1111, scramble=False)
    assert Counter(engine.random().flatten().tolist()) == Counter({0.0: 1111})
    assert Counter(engine.random().flatten().tolist()) == Counter({0.5: 1111})


@pytest.mark.parametrize("bits", [2, 3])
def test_sobol_bits_limit(bits):
    engine = qmckit.Sobol(2, scramble=False, bits=bits)
    ns = 2**bits
    assert_array_equal(scipy_tests.TestSobol.unscramble_nd[:ns], engine.random(ns))
    with pytest.raises(ValueError, match="increasing `bits`"):
        engine.random()


def test_sobol_all_21201_dims():
    a = qmckit.Sobol(21201, scramble=False).random(4)
    b = qmc.Sobol(21201, scramble=False).random(4)
    assert_array_equal(a, b)


# SciPy's test_deterministic, on every qmckit engine.

@pytest.mark.parametrize("engine", ALL_ENGINES, ids=lambda e: e.__name__)
def test_deterministic(engine):
    d = 2 if "PMJ" in engine.__name__ else 1
    seed_number = 2359834584

    rng = np.random.RandomState(seed_number)
    res1 = engine(d=d, seed=rng).random(4)
    rng = np.random.RandomState(seed_number)
    res2 = engine(d=d, seed=rng).random(4)
    assert_array_equal(res1, res2)

    rng = np.random.default_rng(seed_number)
    res1 = engine(d=d, seed=rng).random(4)
    res2 = engine(d=d, rng=seed_number).random(4)
    assert_array_equal(res1, res2)
    rng = np.random.default_rng(seed_number)
    res3 = engine(d=d, rng=rng).random(4)
    assert_array_equal(res2, res1)
    assert_array_equal(res3, res1)

    with pytest.raises(TypeError, match="got multiple values for argument now known as `rng`"):
        engine(d=d, rng=seed_number, seed=seed_number)
