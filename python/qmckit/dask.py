"""Points of a qmckit engine as a Dask array, generated in chunks where Dask runs them.

    import qmckit, qmckit.dask
    engine = qmckit.Sobol(8, rng=1)
    x = qmckit.dask.random(engine, 2**24, chunks=2**20)   # dask.array, (2**24, 8)
    x.mean(axis=0).compute()

Chunk ``k`` holds points ``start + k * chunks ..`` of the engine (``start`` its
``num_generated``), filled by the chunk's task from the engine's native sampler: by
random access, so the chunks need no communication and the array equals
``engine.random(n)``. The engine is sent to process or distributed workers by pickling,
which rebuilds its sampler there from the arguments it was made with (its scramble
included). Requires ``dask[array]`` (not a dependency of qmckit).
"""

from __future__ import annotations

import copy

import numpy as np

__all__ = ["random"]


def _fill(engine, start, rows, dtype):
    out = np.empty((rows, engine.d), dtype=dtype)
    if rows and engine.d:
        engine._native.fill(start, out)
    return out


def random(engine, n, *, chunks=2**16, dtype=np.float64):
    """The next ``n`` points of ``engine`` as a ``dask.array.Array`` of ``(n, d)``.

    ``dtype`` is ``float64`` or ``uint32`` (0.32 fractions, as ``engine.fill``). The
    engine advances by ``n`` (as ``engine.random(n)``). Engines with an ``optimization``,
    and the ones that are not sequences (``LatinHypercube``, ``PoissonDisk``), are
    refused: their points are not a function of the index alone.
    """
    import dask
    import dask.array as da

    from ._engines import _NativeEngine

    dtype = np.dtype(dtype)
    if dtype not in (np.dtype(np.float64), np.dtype(np.uint32)):
        raise TypeError(f"dtype must be float64 or uint32, got {dtype}")
    if not isinstance(engine, _NativeEngine) or getattr(engine, "_native_args", None) is None:
        if not (isinstance(engine, _NativeEngine) and engine.d == 0):
            raise TypeError(
                f"{type(engine).__name__} is not an indexed sequence of qmckit's"
            )
    if engine.optimization_method is not None:
        raise ValueError("an optimization is applied to a whole sample, not to chunks")
    n = int(n)
    chunks = int(chunks)
    if chunks < 1:
        raise ValueError(f"chunks must be positive, got {chunks}")
    engine._check_n(n)
    start = engine.num_generated
    snapshot = dask.delayed(copy.copy(engine), pure=True)
    parts = []
    for a in range(0, n, chunks):
        rows = min(chunks, n - a)
        block = dask.delayed(_fill, pure=True)(snapshot, start + a, rows, dtype)
        parts.append(da.from_delayed(block, shape=(rows, engine.d), dtype=dtype))
    engine.num_generated += n
    if not parts:
        return da.zeros((0, engine.d), dtype=dtype)
    return da.concatenate(parts, axis=0)
