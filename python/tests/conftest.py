"""Shared helpers of the qmckit Python tests."""

import functools

import qmckit


def engine_with(cls, **fixed):
    """``cls`` with some constructor arguments fixed, usable as SciPy's ``qmce``
    (``qmce(d=..., scramble=..., seed=..., **kwargs)``)."""
    factory = functools.partial(cls, **fixed)
    factory.__name__ = f"{cls.__name__}({', '.join(f'{k}={v!r}' for k, v in fixed.items())})"
    return factory


ALL_ENGINES = [
    qmckit.Sobol,
    engine_with(qmckit.Sobol, randomizer="owen"),
    engine_with(qmckit.Sobol, randomizer="lms"),
    engine_with(qmckit.Sobol, randomizer="xor"),
    qmckit.Halton,
    engine_with(qmckit.Halton, randomizer="scipy-perm"),
    engine_with(qmckit.Halton, randomizer="owen"),
    qmckit.LatinHypercube,
    qmckit.Lattice,
    qmckit.Kronecker,
    qmckit.Faure,
    engine_with(qmckit.Faure, randomizer="perm"),
    qmckit.PMJ02,
    qmckit.PMJ02BN,
]
