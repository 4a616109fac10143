"""SciPy's own generic engine tests (``QMCEngineTests`` from the installed SciPy), run on
every qmckit engine.

Deviations, each with its reason:

* ``test_sample[Scrambled]`` compares the first 8 scrambled 2D points with SciPy's
  reference arrays, which are SciPy's scrambles (LMS + shift for Sobol', digit
  permutations for Halton) for one seed. The engines that draw SciPy's scramble the way
  SciPy does (``Sobol(randomizer="lms")``, ``Halton(randomizer="scipy-perm")``) pass it; the
  other randomizers draw a different scramble and are marked ``xfail(strict=True)``
  (they must fail, so the mark cannot hide a change). Engines of qmckit's own (lattice,
  Kronecker, Faure) have no SciPy reference for their scramble: skipped, and their
  unscrambled reference is the construction's theoretical points.
* LatinHypercube skips what SciPy's own ``TestLHS`` skips (not a sequence; reference
  values implementation dependent).
* ``test_optimizers[lloyd]`` asserts that Lloyd's iteration widens the minimum L1
  distance. It does not for the 64-point rank-1 lattice and Kronecker sets, already
  better spread than what the iteration converges to, nor for this seed's Latin
  hypercube design (for SciPy's and qmckit's LHS alike, 4 of 40 seeds do not improve):
  ``xfail(strict=True)``. Nor, for about 40% of seeds with SciPy's sampler and
  qmckit's alike, for the first 64 points of a Poisson-disk set; this seed's qmckit set
  is one.
* ``PoissonDisk`` runs SciPy's whole ``TestPoisson``, which skips what does not apply
  to a Poisson-disk process.
* PMJ02 and PMJ02BN are two-dimensional and always random: the tests in other
  dimensions (``d=0``, ``d=100``) and against a reference sample are skipped.
"""

import numpy as np
import pytest
from scipy.stats.tests import test_qmc as scipy_tests
from scipy.stats.tests.test_qmc import QMCEngineTests

import qmckit
from conftest import engine_with

SCIPY_SOBOL = scipy_tests.TestSobol
SCIPY_HALTON = scipy_tests.TestHalton

SCRAMBLE = [True, False]
IDS = ["Scrambled", "Unscrambled"]


def _xfail_scrambled_sample(reason):
    """``test_sample`` with the scrambled case expected to fail (strict)."""
    params = [
        pytest.param(True, marks=pytest.mark.xfail(strict=True, reason=reason)),
        False,
    ]

    @pytest.mark.parametrize("scramble", params, ids=IDS)
    def test_sample(self, scramble):
        QMCEngineTests.test_sample(self, scramble)

    return test_sample


def _skip_scrambled_sample(reason):
    @pytest.mark.parametrize("scramble", SCRAMBLE, ids=IDS)
    def test_sample(self, scramble):
        if scramble:
            pytest.skip(reason)
        QMCEngineTests.test_sample(self, scramble)

    return test_sample


def _xfail_lloyd(reason):
    """``test_optimizers`` with the Lloyd case expected to fail (strict)."""
    import scipy.stats.qmc as qmc
    from scipy.stats._qmc import _l1_norm

    params = [
        ("random-CD", qmc.discrepancy),
        pytest.param(
            "lloyd",
            lambda sample: -_l1_norm(sample),
            marks=pytest.mark.xfail(strict=True, reason=reason),
        ),
    ]

    @pytest.mark.parametrize("optimization,metric", params)
    def test_optimizers(self, optimization, metric):
        QMCEngineTests.test_optimizers(self, optimization, metric)

    return test_optimizers


ALREADY_SPREAD = (
    "the 64 unscrambled points are already better spread (minimum L1 distance) than "
    "what SciPy's Lloyd iteration in the box converges to; the test assumes the "
    "optimization improves on the engine's points"
)

OTHER_SOBOL_SCRAMBLE = (
    "SciPy's reference is its LMS + shift scramble for this seed; this randomizer "
    "draws another scramble"
)


class TestSobol(QMCEngineTests):
    """The default randomizer (``"fast-owen"``)."""

    qmce = qmckit.Sobol
    can_scramble = True
    unscramble_nd = SCIPY_SOBOL.unscramble_nd
    scramble_nd = SCIPY_SOBOL.scramble_nd
    test_sample = _xfail_scrambled_sample(OTHER_SOBOL_SCRAMBLE)


class TestSobolOwen(QMCEngineTests):
    qmce = engine_with(qmckit.Sobol, randomizer="owen")
    can_scramble = True
    unscramble_nd = SCIPY_SOBOL.unscramble_nd
    scramble_nd = SCIPY_SOBOL.scramble_nd
    test_sample = _xfail_scrambled_sample(OTHER_SOBOL_SCRAMBLE)


class TestSobolFastOwen(QMCEngineTests):
    qmce = engine_with(qmckit.Sobol, randomizer="fast-owen")
    can_scramble = True
    unscramble_nd = SCIPY_SOBOL.unscramble_nd
    scramble_nd = SCIPY_SOBOL.scramble_nd
    test_sample = _xfail_scrambled_sample(OTHER_SOBOL_SCRAMBLE)


class TestSobolXor(QMCEngineTests):
    qmce = engine_with(qmckit.Sobol, randomizer="xor")
    can_scramble = True
    unscramble_nd = SCIPY_SOBOL.unscramble_nd
    scramble_nd = SCIPY_SOBOL.scramble_nd
    test_sample = _xfail_scrambled_sample(OTHER_SOBOL_SCRAMBLE)


class TestSobolLMS(QMCEngineTests):
    """SciPy's scramble drawn as SciPy draws it: SciPy's reference arrays hold."""

    qmce = engine_with(qmckit.Sobol, randomizer="lms")
    can_scramble = True
    unscramble_nd = SCIPY_SOBOL.unscramble_nd
    scramble_nd = SCIPY_SOBOL.scramble_nd


class TestHaltonScipyPerm(QMCEngineTests):
    """SciPy's permutations and arithmetic: SciPy's reference holds."""

    qmce = engine_with(qmckit.Halton, randomizer="scipy-perm")
    can_scramble = True
    unscramble_nd = SCIPY_HALTON.unscramble_nd
    scramble_nd = SCIPY_HALTON.scramble_nd

    def test_workers(self):
        SCIPY_HALTON.test_workers(self)


class TestHaltonPerm(QMCEngineTests):
    """The default Halton: qmckit's digit permutations in 0.32 fixed point."""

    qmce = qmckit.Halton
    can_scramble = True
    unscramble_nd = SCIPY_HALTON.unscramble_nd
    scramble_nd = SCIPY_HALTON.scramble_nd
    test_sample = _xfail_scrambled_sample(
        "SciPy's reference is its random digit permutations drawn from this seed; qmckit's "
        "permutations are keyed by a seed drawn from it"
    )


class TestHaltonOwen(QMCEngineTests):
    qmce = engine_with(qmckit.Halton, randomizer="owen")
    can_scramble = True
    unscramble_nd = SCIPY_HALTON.unscramble_nd
    scramble_nd = SCIPY_HALTON.scramble_nd
    test_sample = _xfail_scrambled_sample(
        "SciPy's reference is its random digit permutations for this seed; Owen "
        "scrambling in base b draws another scramble"
    )


class TestLHS(QMCEngineTests):
    qmce = qmckit.LatinHypercube
    can_scramble = True

    def test_continuing(self, *args):
        pytest.skip("Not applicable: not a sequence.")

    def test_fast_forward(self, *args):
        pytest.skip("Not applicable: not a sequence.")

    def test_sample(self, *args):
        pytest.skip("Not applicable: the reference sample is implementation dependent.")

    # Whether Lloyd's iteration widens the minimum L1 distance of a centered 64-point LHS
    # depends on the design: 36 of seeds 0..39 do for SciPy's LHS and 36 for qmckit's; the
    # test's seed draws a qmckit design that does not.
    test_optimizers = _xfail_lloyd(
        "Lloyd's iteration does not widen the minimum L1 distance of every LHS design "
        "(36 of 40 seeds for SciPy's and for qmckit's); this seed's qmckit design is one"
    )

    def test_optimizer_1d(self):
        SCIPY_LHS = scipy_tests.TestLHS
        SCIPY_LHS.test_optimizer_1d(self)


class TestLHSScipyOwnTests:
    """SciPy's ``TestLHS`` tests that construct ``qmc.LatinHypercube`` themselves
    (strength 1 and 2, stratification and every 2-D projection of the orthogonal array,
    the errors), run with ``qmc.LatinHypercube`` replaced by qmckit's."""

    @pytest.fixture(autouse=True)
    def _qmckit_lhs(self, monkeypatch):
        monkeypatch.setattr(scipy_tests.qmc, "LatinHypercube", qmckit.LatinHypercube)

    @pytest.mark.parametrize("strength", [1, 2])
    @pytest.mark.parametrize("scramble", [False, True])
    @pytest.mark.parametrize("optimization", [None, "random-CD"])
    def test_sample_stratified(self, optimization, scramble, strength):
        assert scipy_tests.qmc.LatinHypercube is qmckit.LatinHypercube
        scipy_tests.TestLHS.test_sample_stratified(
            scipy_tests.TestLHS(), optimization, scramble, strength
        )

    def test_raises(self):
        scipy_tests.TestLHS.test_raises(scipy_tests.TestLHS())


def _radical_inverse_2(i):
    x, f = 0.0, 0.5
    while i:
        x += f * (i & 1)
        i >>= 1
        f /= 2
    return x


# Kuo's generating vector starts (1, 182667): x_i = frac(phi_2(i) z).
LATTICE_2D = np.array(
    [[_radical_inverse_2(i) * z % 1.0 for z in (1, 182667)] for i in range(8)]
)

# R_2: alpha = (1/g, 1/g^2), g the plastic number (g^3 = g + 1).
_G = 1.32471795724474602596
KRONECKER_2D = np.array([[(i / _G) % 1.0, (i / _G**2) % 1.0] for i in range(8)])


def _faure_base2(i):
    """Faure's sequence in base 2, 2D: (phi_2(i), phi_2(P i)) with P Pascal's matrix
    mod 2."""
    digits = [(i >> k) & 1 for k in range(3)]
    y = [sum((1 if (c >= r and (c & r) == r) else 0) * digits[c] for c in range(3)) % 2
         for r in range(3)]
    return [_radical_inverse_2(i), sum(b / 2 ** (k + 1) for k, b in enumerate(y))]


FAURE_2D = np.array([_faure_base2(i) for i in range(8)])

NO_REFERENCE = "no external reference for qmckit's own scramble of this construction"


class TestLattice(QMCEngineTests):
    qmce = qmckit.Lattice
    can_scramble = True
    unscramble_nd = LATTICE_2D
    test_sample = _skip_scrambled_sample(NO_REFERENCE)
    test_optimizers = _xfail_lloyd("rank-1 lattice: " + ALREADY_SPREAD)


class TestKronecker(QMCEngineTests):
    qmce = qmckit.Kronecker
    can_scramble = True
    unscramble_nd = KRONECKER_2D
    test_sample = _skip_scrambled_sample(NO_REFERENCE)
    test_optimizers = _xfail_lloyd("R_2 Kronecker sequence: " + ALREADY_SPREAD)


class TestFaure(QMCEngineTests):
    qmce = qmckit.Faure
    can_scramble = True
    unscramble_nd = FAURE_2D
    test_sample = _skip_scrambled_sample(NO_REFERENCE)


class TestFaurePerm(QMCEngineTests):
    qmce = engine_with(qmckit.Faure, randomizer="perm")
    can_scramble = True
    unscramble_nd = FAURE_2D
    test_sample = _skip_scrambled_sample(NO_REFERENCE)


class _TwoDimensional(QMCEngineTests):
    can_scramble = False

    def test_0dim(self, *args):
        pytest.skip("Not applicable: PMJ sequences are two-dimensional.")

    def test_bounds(self, *args):
        pytest.skip("Not applicable: PMJ sequences are two-dimensional (d=100 asked).")

    def test_sample(self, *args):
        pytest.skip("Not applicable: a stochastic construction has no reference sample.")


class TestPMJ02(_TwoDimensional):
    qmce = qmckit.PMJ02


class TestPMJ02BN(_TwoDimensional):
    qmce = qmckit.PMJ02BN


class TestPoissonDisk(scipy_tests.TestPoisson):
    """SciPy's whole ``TestPoisson`` (its generic tests and its Poisson-disk tests:
    minimum distance, bounds, shift and scale, errors), on ``qmckit.PoissonDisk``."""

    qmce = qmckit.PoissonDisk
    test_optimizers = _xfail_lloyd(
        "Lloyd's iteration widens the minimum L1 distance of the first 64 Poisson-disk "
        "points for 18 of seeds 0..29 with SciPy's sampler and 19 with qmckit's; the "
        "test's seed draws a qmckit set that it does not"
    )
