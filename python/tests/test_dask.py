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
