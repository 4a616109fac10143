"""The native layer: in-place fills (zero copy), threads, the GIL, 32-bit index limits,
errors, and integration through ``scipy.integrate.qmc_quad``."""

import threading
import time

import numpy as np
import pytest
from numpy.testing import assert_array_equal
from scipy.integrate import qmc_quad
from scipy.stats import qmc

import qmckit
from qmckit import _qmckit
from conftest import ALL_ENGINES

# -- zero copy ---------------------------------------------------------------------------
#
# Checked by ownership: the caller's array is filled in place and returned. The array is
# first poisoned with NaN (uint32: a sentinel); after the fill it holds the points, the
# returned object *is* the caller's array, and the native layer refuses (rather than
# copies) an array it could not fill in place: Fortran order, a strided view, a
# read-only array, another dtype.


@pytest.mark.parametrize("engine", ALL_ENGINES, ids=lambda e: e.__name__)
def test_random_out_is_filled_in_place(engine):
    d = 2
    ref = engine(d=d, rng=3).random(256)
    buf = np.full((256, d), np.nan)
    eng = engine(d=d, rng=3)
    got = eng.random(256, out=buf)
    assert got is buf
    assert np.shares_memory(got, buf)
    assert_array_equal(buf, ref)
    assert eng.num_generated == 256


def test_fill_uint32_is_exact_and_in_place():
    eng = qmckit.Sobol(3, scramble=False, bits=32)
    buf = np.full((1024, 3), 0xDEADBEEF, dtype=np.uint32)
    assert eng.fill(buf) is buf
    x = qmckit.Sobol(3, scramble=False, bits=32).random(1024)
    assert_array_equal(buf / 2.0**32, x)
    assert eng.num_generated == 1024


def test_native_fill_writes_caller_memory():
    s = _qmckit.sobol(4, 32)
    base = np.zeros((10, 4))
    s.fill(6, base)
    assert_array_equal(base, qmc.Sobol(4, scramble=False, bits=32).random(16)[6:])


# Allocation checks: NumPy reports its array buffers to tracemalloc, so a hidden copy of
# an (n, d) array (or a temporary of its size) shows in the peak. Each test first shows
# that a copy *is* seen (the check can fail), then that the call makes none.

_BIG = (1 << 17, 8)  # 8 MiB of float64
_BYTES = _BIG[0] * _BIG[1] * 8


def _peak(fn):
    import tracemalloc

    tracemalloc.start()
    try:
        tracemalloc.reset_peak()
        base = tracemalloc.get_traced_memory()[0]
        fn()
        return tracemalloc.get_traced_memory()[1] - base
    finally:
        tracemalloc.stop()


def test_a_copy_shows_in_the_peak():
    x = np.zeros(_BIG)
    assert _peak(lambda: np.array(x, copy=True)) >= _BYTES


@pytest.mark.parametrize("randomizer", ["owen", "fast-owen", "lms", "xor"])
@pytest.mark.parametrize("dtype", [np.float64, np.uint32])
def test_fill_allocates_no_array(randomizer, dtype):
    out = np.zeros(_BIG, dtype=dtype)
    ptr = out.__array_interface__["data"][0]
    eng = qmckit.Sobol(_BIG[1], randomizer=randomizer, rng=2)
    if dtype is np.float64:
        peak = _peak(lambda: eng.random(_BIG[0], out=out))
    else:
        peak = _peak(lambda: eng.fill(out))
    assert out.__array_interface__["data"][0] == ptr
    assert peak < out.nbytes // 16
    assert out.any()


@pytest.mark.parametrize("method", ["CD", "L2-star"])
def test_discrepancy_does_not_copy_a_c_contiguous_input(method):
    x = qmckit.Sobol(_BIG[1], rng=1).random(1 << 12)
    big = np.repeat(x, 8, axis=0)  # 2^15 x 8
    assert _peak(lambda: qmckit.discrepancy(big[:64], method=method)) < 4096
    # The check can fail: a Fortran-order input is converted (copied) first.
    f = np.asfortranarray(big)
    assert _peak(lambda: qmckit.discrepancy(f[:2048], method=method)) >= 2048 * 8 * 8
    assert _peak(lambda: qmckit.discrepancy(big[:2048], method=method)) < 2048 * 8

@pytest.mark.parametrize(
    "make",
    [
        lambda: np.zeros((8, 4), order="F"),
        lambda: np.zeros((8, 8))[:, ::2],
        lambda: np.zeros((8, 4), dtype=np.float32),
        lambda: np.zeros((8, 5)),
        lambda: np.zeros(32),
    ],
    ids=["fortran", "strided", "float32", "wrong-dims", "1-d"],
)
def test_native_fill_refuses_what_it_cannot_fill_in_place(make):
    s = _qmckit.sobol(4, 32)
    with pytest.raises((ValueError, TypeError)):
        s.fill(0, make())


def test_native_fill_refuses_read_only():
    s = _qmckit.sobol(4, 32)
    a = np.zeros((8, 4))
    a.flags.writeable = False
    with pytest.raises((ValueError, TypeError)):
        s.fill(0, a)


# -- threads -----------------------------------------------------------------------------


@pytest.mark.filterwarnings("ignore:The balance properties")
@pytest.mark.parametrize("engine", ALL_ENGINES, ids=lambda e: e.__name__)
def test_workers_do_not_change_the_points(engine):
    n = 5000 if "PMJ02BN" not in engine.__name__ else 2**12
    one = engine(d=2, rng=9).random(n)
    assert_array_equal(engine(d=2, rng=9).random(n, workers=2), one)
    assert_array_equal(engine(d=2, rng=9).random(n, workers=-1), one)
    assert_array_equal(engine(d=2, rng=9).random(n, workers=7), one)


def test_large_parallel_fill_equals_serial():
    a = qmckit.Halton(8, rng=2).random(100_000, workers=1)
    b = qmckit.Halton(8, rng=2).random(100_000, workers=3)
    assert_array_equal(a, b)
    a = qmckit.Sobol(8, rng=2).random(2**17, workers=1)
    b = qmckit.Sobol(8, rng=2).random(2**17, workers=2)
    assert_array_equal(a, b)


def test_gil_is_released_during_long_fills():
    """Another Python thread runs while a long fill is in progress."""
    eng = qmckit.Sobol(8, rng=1)
    buf = np.empty((2**21, 8))
    done = threading.Event()
    ticks = 0

    def work():
        eng.random(2**21, out=buf)
        done.set()

    t = threading.Thread(target=work)
    t.start()
    while not done.is_set():
        ticks += 1
        time.sleep(0)
    t.join()
    assert ticks > 10


# -- 32-bit indices ----------------------------------------------------------------------


def test_sobol_refuses_past_two_to_the_32():
    eng = qmckit.Sobol(2, scramble=False, bits=32)
    eng.fast_forward(2**32 - 4)
    last = eng.random(4)
    ref = np.empty((4, 2), dtype=np.uint32)
    _qmckit.sobol(2, 32).fill(2**32 - 4, ref)
    assert_array_equal(last, ref / 2.0**32)
    with pytest.raises(ValueError, match=r"At most 2\*\*32=4294967296 distinct points"):
        eng.random(1)


@pytest.mark.parametrize("engine", [qmckit.Halton, qmckit.Kronecker, qmckit.PMJ02,
                                    qmckit.Faure], ids=lambda e: e.__name__)
def test_sequences_refuse_past_two_to_the_32(engine):
    eng = engine(d=2, rng=1)
    eng.fast_forward(2**32 - 2)
    assert eng.random(2).shape == (2, 2)
    with pytest.raises(ValueError, match="32-bit"):
        eng.random(1)


def test_native_refuses_start_past_two_to_the_32():
    s = _qmckit.halton(2)
    with pytest.raises(ValueError, match="32-bit"):
        s.fill(2**32, np.zeros((1, 2)))
    with pytest.raises(ValueError, match="32-bit"):
        s.fill(2**32 - 1, np.zeros((2, 2)))


def test_finite_sets_refuse_past_their_end():
    eng = qmckit.Lattice(3, rng=1)
    assert eng.maxn == 2**20
    eng.fast_forward(2**20 - 1)
    eng.random(1)
    with pytest.raises(ValueError, match="1048576"):
        eng.random(1)
    bn = qmckit.PMJ02BN(rng=1, max_points=64)
    bn.random(64)
    with pytest.raises(ValueError, match="64"):
        bn.random(1)


# -- errors ------------------------------------------------------------------------------


@pytest.mark.parametrize(
    "make, match",
    [
        (lambda: qmckit.Halton(2000, randomizer="owen"), "dimension"),
        (lambda: qmckit.Halton(2000), "scipy-perm"),
        (lambda: qmckit.Lattice(10_000), "dimension"),
        (lambda: qmckit.Sobol(2, randomizer="nope"), "not a valid randomizer"),
        (lambda: qmckit.Halton(2, randomizer="nope"), "not a valid randomizer"),
        (lambda: qmckit.PMJ02(3), "two-dimensional"),
        (lambda: qmckit.LatinHypercube(2, strength=3), "not a valid strength"),
        (lambda: qmckit.Sobol(2, optimization="toto"), "not a valid optimization"),
        (lambda: _qmckit.sobol(0), "dimension"),
        (lambda: _qmckit.latin_hypercube(0, 2, 1), "point"),
        (lambda: _qmckit.pmj02bn(2**31, 1), "point"),
        (lambda: _qmckit.halton_scipy([1]), "base"),
    ],
)
def test_errors_are_value_errors_with_qmckits_message(make, match):
    with pytest.raises(ValueError, match=match) as info:
        make()
    assert "panic" not in str(info.value).lower()


# -- integration -------------------------------------------------------------------------


@pytest.mark.parametrize("engine", ALL_ENGINES, ids=lambda e: e.__name__)
def test_qmc_quad(engine):
    """scipy.integrate.qmc_quad builds fresh engines from ``_init_quad``."""
    d = 2 if "PMJ" in engine.__name__ else 3

    def f(x):  # x has shape (d, n)
        return np.prod(x, axis=0) * 2**d

    res = qmc_quad(f, np.zeros(d), np.ones(d), n_points=1024, n_estimates=8,
                   qrng=engine(d=d, rng=11))
    assert abs(res.integral - 1.0) < max(5 * res.standard_error, 1e-6)
    assert res.standard_error < 0.01


def test_qmc_quad_keeps_the_randomizer(monkeypatch):
    """The engines qmc_quad builds from ``_init_quad`` have the same randomizer."""
    seen = []
    orig = qmckit.Sobol._build

    def spy(self):
        seen.append(self.randomizer)
        return orig(self)

    monkeypatch.setattr(qmckit.Sobol, "_build", spy)
    eng = qmckit.Sobol(2, randomizer="lms", rng=1)
    res = qmc_quad(lambda x: np.sum(x, axis=0), [0, 0], [1, 1], qrng=eng, n_estimates=4)
    assert abs(res.integral - 1.0) < 1e-6
    assert seen == ["lms"] * 5


# -- Poisson disk ------------------------------------------------------------------------


@pytest.mark.parametrize("d, radius", [(1, 0.01), (2, 0.02), (3, 0.1), (5, 0.3)])
def test_poisson_disk_spacing_and_coverage(d, radius):
    from scipy.spatial.distance import pdist

    eng = qmckit.PoissonDisk(d, radius=radius, rng=5)
    x = eng.fill_space()
    assert pdist(x).min() >= radius
    assert np.all((x >= 0) & (x < 1))
    # Saturated: no point of a fine random probe set is farther than 2 r from the set.
    from scipy.spatial import cKDTree

    probe = np.random.default_rng(0).random((2000, d))
    dist, _ = cKDTree(x).query(probe)
    assert dist.max() < 2 * radius


def test_poisson_disk_rectangle_and_continuation():
    from scipy.spatial.distance import pdist

    eng = qmckit.PoissonDisk(2, radius=0.1, l_bounds=[0, -1], u_bounds=[4, 1], rng=2)
    a = eng.random(50)
    b = eng.fill_space()
    x = np.concatenate([a, b])
    assert pdist(x).min() >= 0.1
    assert np.all((x >= [0, -1]) & (x < [4, 1]))
    assert len(eng.random(5)) == 0
    eng.reset()
    assert_array_equal(eng.random(50), a)


def test_poisson_disk_refuses_above_eight_dimensions():
    with pytest.raises(ValueError, match="dimension"):
        qmckit.PoissonDisk(9, radius=0.5).random(1)


@pytest.mark.parametrize("randomizer", ["perm", "owen"])
def test_halton_fill_any_split(randomizer):
    """qmckit's Halton scrambles filled in one call, in uneven chunks (runs starting
    inside the digit tables) and as 0.32 integers: the same values."""
    whole = qmckit.Halton(8, rng=5, randomizer=randomizer).random(5000)
    e = qmckit.Halton(8, rng=5, randomizer=randomizer)
    parts = np.vstack([e.random(k) for k in (1, 7, 1000, 2992, 1000)])
    np.testing.assert_array_equal(whole, parts)
    raw = np.empty((5000, 8), dtype=np.uint32)
    qmckit.Halton(8, rng=5, randomizer=randomizer).fill(raw)
    np.testing.assert_array_equal(whole, raw / 2**32)


def test_halton_many_dims_scipy_perm():
    x = qmckit.Halton(2000, rng=1, randomizer="scipy-perm").random(4)
    assert x.shape == (4, 2000)


@pytest.mark.filterwarnings("ignore:The balance properties")
@pytest.mark.parametrize("randomizer", ["owen", "fast-owen", "lms", "xor"])
def test_sobol_fill_any_split(randomizer):
    """The batched Sobol' fills (exact Owen's tabled one; the others through the chunked
    0.32 fill, masked and converted): one call, uneven chunks, several threads and 0.32
    integers give the same values, kept to ``bits`` bits."""
    def make():
        return qmckit.Sobol(5, rng=3, randomizer=randomizer)

    whole = make().random(40000)
    e = make()
    parts = np.vstack([e.random(k) for k in (1, 3, 2044, 3952, 33000, 1000)])
    np.testing.assert_array_equal(whole, parts)
    np.testing.assert_array_equal(whole, make().random(40000, workers=3))
    raw = np.empty((40000, 5), dtype=np.uint32)
    make().fill(raw)
    np.testing.assert_array_equal(whole, raw / 2**32)
    assert np.all(raw % 4 == 0)  # bits=30


@pytest.mark.filterwarnings("ignore:The balance properties")
@pytest.mark.parametrize("d", [1, 4, 8, 20, 70])
@pytest.mark.parametrize("bits", [30, 17, 12])
def test_fast_owen_bits_truncates_the_32_bit_points(d, bits):
    """``bits`` keeps the top ``bits`` bits of the 32-bit scrambled points (coordinates
    are multiples of ``2**-bits``, as SciPy's): the ``float64`` fill (the mask inside the
    scramble loop), the ``uint32`` fill and the 32-bit points floored to that grid agree,
    for point widths laid over rows (up to 64 dimensions) and wider ones."""
    n = 3000
    full = qmckit.Sobol(d, rng=4, bits=32).random(n)
    x = qmckit.Sobol(d, rng=4, bits=bits).random(n)
    np.testing.assert_array_equal(x, np.floor(full * 2**bits) / 2**bits)
    raw = np.empty((n, d), dtype=np.uint32)
    qmckit.Sobol(d, rng=4, bits=bits).fill(raw)
    np.testing.assert_array_equal(x, raw / 2**32)
    assert np.all(raw % (1 << (32 - bits)) == 0)
    # Not all zero below the kept bits when bits=32 (the check can fail).
    assert np.any(full * 2**bits % 1 != 0)


# -- LatinHypercube(strength=2) and PoissonDisk(hypersphere="surface") ------------------


@pytest.mark.parametrize("p, d", [(2, 3), (3, 4), (7, 8), (11, 5)])
def test_oa_lhs_is_a_latin_hypercube_with_full_2d_projections(p, d):
    n = p * p
    x = qmckit.LatinHypercube(d, strength=2, rng=5).random(n)
    assert x.shape == (n, d)
    assert np.all((0 <= x) & (x < 1))
    # Latin: every one of the n slabs of every axis holds one point.
    for j in range(d):
        assert sorted((x[:, j] * n).astype(int)) == list(range(n))
    # Strength 2: every pair of axes puts one point in each of the p x p cells.
    cells = (x * p).astype(int)
    for i in range(d):
        for j in range(i + 1, d):
            assert len({(a, b) for a, b in cells[:, [i, j]]}) == n


def test_oa_lhs_draws_new_designs_and_repeats_with_rng():
    a = qmckit.LatinHypercube(3, strength=2, rng=1).random(25)
    b = qmckit.LatinHypercube(3, strength=2, rng=1).random(25)
    assert_array_equal(a, b)
    e = qmckit.LatinHypercube(3, strength=2, rng=1)
    e.random(25)
    assert not np.array_equal(e.random(25), a)


@pytest.mark.parametrize("n, d", [(16, 2), (5, 2), (9, 5), (0, 2)])
def test_oa_lhs_refuses_what_scipy_refuses(n, d):
    with pytest.raises(ValueError) as ours:
        qmckit.LatinHypercube(d, strength=2, rng=1).random(n)
    with pytest.raises(ValueError) as theirs:
        qmc.LatinHypercube(d, strength=2, rng=1).random(n)
    assert str(ours.value).split(".")[0] == str(theirs.value).split(".")[0]


def test_poisson_surface_points_touch_their_neighbour():
    """Surface candidates: every point but the first lies 1.001 r from the point it grew
    from, so its nearest neighbour is within 1.001 r; none is closer than r. Volume
    candidates leave most points farther from their nearest neighbour."""
    from scipy.spatial import cKDTree

    r = 0.03

    def nn(hypersphere):
        x = qmckit.PoissonDisk(2, radius=r, hypersphere=hypersphere, rng=4).fill_space()
        dist, _ = cKDTree(x).query(x, k=2)
        return dist[:, 1]

    surface, volume = nn("surface"), nn("volume")
    assert surface.min() >= r and volume.min() >= r
    assert np.sum(surface > 1.001 * r + 1e-9) <= 1
    assert np.mean(volume <= 1.001 * r + 1e-9) < 0.5
    # Denser than the shell's set, as with SciPy's two methods.
    assert len(surface) > len(volume)
def test_catalog_set_gives_the_command_s_finite_sets():
    """Any finite catalog set by name: the command's bits (`qmckit points NAME -n N`),
    its strata for cmj, and refusals for sequences and bad sizes."""
    import numpy as np
    import pytest

    from qmckit import _qmckit as q

    for name, d in [("cmj", 2), ("cmj", 3), ("hex", 2), ("lloyd", 2), ("ccvt", 3), ("sot", 2), ("bnot", 2),
                    ("projective-blue-noise", 3), ("forced-random", 2), ("ldbn", 2), ("penrose", 2),
                    ("kde-blue-noise", 2), ("aa-patterns", 2), ("art", 2)]:
        s = q.catalog_set(name, 16, d=d, seed=3)
        assert (s.len, s.dims) == (16, d)
        out = np.empty((16, d), dtype=np.uint32)
        s.fill(0, out)
        again = np.empty((16, d), dtype=np.uint32)
        q.catalog_set(name, 16, d=d, seed=3).fill(0, again)
        assert (out == again).all()
    # CMJ of 16 points: one point in each of the 16 columns and rows.
    s = q.catalog_set("cmj", 16, seed=9)
    x = np.empty((16, 2), dtype=np.uint32)
    s.fill(0, x)
    cells = (x.astype(np.uint64) * 16) >> 32
    assert sorted(cells[:, 0]) == list(range(16)) and sorted(cells[:, 1]) == list(range(16))
    for bad in [("sobol", 16), ("hex", 15), ("lloyd", 0)]:
        with pytest.raises(ValueError):
            q.catalog_set(*bad)
    # The kernel-density set's temperature reaches the construction; other sets refuse it.
    cold, hot = (np.empty((64, 2), dtype=np.uint32) for _ in range(2))
    q.catalog_set("kde-blue-noise", 64, seed=1, temperature=0.002).fill(0, cold)
    q.catalog_set("kde-blue-noise", 64, seed=1, temperature=2.0).fill(0, hot)
    assert (cold != hot).any()
    with pytest.raises(ValueError):
        q.catalog_set("lloyd", 16, temperature=0.1)
