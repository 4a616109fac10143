"""Pickling of engines, and the Dask arrays of ``qmckit.dask`` (skipped without Dask)."""

import pickle

import numpy as np
import pytest
from numpy.testing import assert_array_equal

import qmckit
from conftest import ALL_ENGINES


@pytest.mark.parametrize("engine", ALL_ENGINES, ids=lambda e: e.__name__)
def test_pickle_round_trip_keeps_the_points(engine):
    e = engine(d=2, rng=4)
    e.random(16)
    f = pickle.loads(pickle.dumps(e))
    assert f.num_generated == 16
    assert_array_equal(f.random(32), e.random(32))


def test_pickled_poisson_disk():
    e = qmckit.PoissonDisk(2, radius=0.1, rng=1)
    a = e.random(5)
    f = pickle.loads(pickle.dumps(e))
    assert_array_equal(f.random(5), e.random(5))
    assert len(a) == 5


da = pytest.importorskip("dask.array")
import qmckit.dask  # noqa: E402


@pytest.mark.filterwarnings("ignore:The balance properties")
@pytest.mark.parametrize("engine", [qmckit.Sobol, qmckit.Halton, qmckit.Lattice],
                         ids=lambda e: e.__name__)
@pytest.mark.parametrize("scheduler", ["threads", "processes"])
def test_dask_array_equals_random(engine, scheduler):
    e = engine(d=3, rng=2)
    e.random(7)
    x = qmckit.dask.random(e, 10_000, chunks=3000)
    assert x.shape == (10_000, 3)
    assert x.numblocks == (4, 1)
    assert e.num_generated == 10_007
    ref = engine(d=3, rng=2)
    ref.random(7)
    assert_array_equal(x.compute(scheduler=scheduler), ref.random(10_000))


def test_dask_uint32_and_refusals():
    import qmckit.dask

    x = qmckit.dask.random(qmckit.Sobol(2, scramble=False, bits=32), 8, dtype=np.uint32)
    assert_array_equal(x.compute() / 2.0**32, qmckit.Sobol(2, scramble=False).random(8))
    with pytest.raises(TypeError):
        qmckit.dask.random(qmckit.LatinHypercube(2), 8)
    with pytest.raises(ValueError, match="optimization"):
        qmckit.dask.random(qmckit.Halton(2, optimization="random-cd"), 8)
    with pytest.raises(ValueError, match="32-bit"):
        qmckit.dask.random(qmckit.Halton(2).fast_forward(2**32 - 1), 2)


def test_dask_distributed_local_cluster():
    distributed = pytest.importorskip("dask.distributed")
    import qmckit.dask

    with distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                  dashboard_address=None) as cluster, \
            distributed.Client(cluster) as client:
        e = qmckit.Sobol(4, randomizer="lms", rng=5)
        x = qmckit.dask.random(e, 2**14, chunks=2**12)
        got = client.compute(x).result()
    assert_array_equal(got, qmckit.Sobol(4, randomizer="lms", rng=5).random(2**14))


def _estimate(x):
    """A QMC estimate of the integral of prod_j (1 + (x_j - 1/2)) over [0, 1]^d (exactly 1)."""
    return (1.0 + (x - 0.5)).prod(axis=1).mean()


def test_dask_estimate_identical_on_1_2_4_worker_processes():
    """The same estimate, bit for bit, whether 1, 2 or 4 worker processes compute the
    chunks (each worker rebuilds the scramble from the pickled engine): the default
    randomizer, exact Owen and SciPy's LMS."""
    distributed = pytest.importorskip("dask.distributed")
    n, chunks = 2**15, 2**12
    randomizers = ["fast-owen", "owen", "lms"]
    got = {}
    for workers in (1, 2, 4):
        with distributed.LocalCluster(n_workers=workers, threads_per_worker=1,
                                      processes=True, dashboard_address=None) as cluster, \
                distributed.Client(cluster) as client:
            assert len(client.scheduler_info()["workers"]) == workers
            ests = [_estimate(qmckit.dask.random(qmckit.Sobol(5, randomizer=r, rng=11),
                                                 n, chunks=chunks))
                    for r in randomizers]
            got[workers] = client.gather(client.compute(ests))
    assert got[1] == got[2] == got[4]
    for r, est in zip(randomizers, got[1]):
        ref = _estimate(qmckit.Sobol(5, randomizer=r, rng=11).random(n))
        assert abs(est - ref) < 1e-12
        assert abs(est - 1.0) < 1e-3  # an estimate of the integral, not noise


def test_dask_estimate_identical_with_the_process_scheduler():
    """dask's multiprocessing scheduler with 1, 2 and 4 processes: the same value."""
    e = qmckit.Halton(4, rng=3)
    x = qmckit.dask.random(e, 2**14, chunks=2**11)
    est = _estimate(x)
    vals = [est.compute(scheduler="processes", num_workers=w) for w in (1, 2, 4)]
    assert vals[0] == vals[1] == vals[2]
