"""qmckit's engines as a QMCPy discrete distribution.

    from qmcpy import Keister, CubQMCRepStudentT
    from qmckit.qmcpy import QMCKit

    k = Keister(QMCKit(3, replications=16, seed=7, engine="Sobol"))
    solution, data = CubQMCRepStudentT(k, abs_tol=1e-3).integrate()

Each replication is an independently randomized engine (its ``rng`` spawned from the
distribution's seed), and ``gen_samples(n_min=a, n_max=b)`` returns points ``a .. b-1``
of every replication by random access. Requires ``qmcpy`` (not a dependency of qmckit).
"""

from __future__ import annotations

import warnings

import numpy as np
from qmcpy.discrete_distribution.abstract_discrete_distribution import (
    AbstractLDDiscreteDistribution,
)
from qmcpy.util import ParameterError

from . import _engines

__all__ = ["QMCKit"]

_ENGINES = {
    "Sobol": _engines.Sobol,
    "Halton": _engines.Halton,
    "Lattice": _engines.Lattice,
    "Kronecker": _engines.Kronecker,
    "Faure": _engines.Faure,
}

_D_LIMITS = {"Sobol": 21201, "Halton": 10_000, "Lattice": 9125, "Kronecker": 2**16,
             "Faure": 10_000}
_N_LIMITS = {"Lattice": 2**20}


class QMCKit(AbstractLDDiscreteDistribution):
    """A QMCPy low-discrepancy distribution drawing from a qmckit engine.

    Args:
        dimension (int or array of ints): the dimension, or the dimensions to keep.
        replications (None or int): independent randomizations (``None``: one, and
            ``gen_samples`` returns ``(n, d)`` rather than ``(replications, n, d)``).
        seed (None, int or numpy.random.SeedSequence): the randomization seed.
        engine (str): ``"Sobol"``, ``"Halton"``, ``"Lattice"``, ``"Kronecker"`` or
            ``"Faure"``.
        randomize (bool): scramble (the engine's ``scramble``).
        **engine_kwargs: passed to the engine (e.g. ``randomizer="owen"``, exact Owen).
    """

    def __init__(self, dimension=1, replications=None, seed=None, engine="Sobol",
                 randomize=True, **engine_kwargs):
        if engine not in _ENGINES:
            raise ParameterError(f"engine must be one of {sorted(_ENGINES)}, got {engine!r}")
        self.engine = engine
        self.engine_kwargs = dict(engine_kwargs)
        self.parameters = ["engine", "randomize"]
        super().__init__(dimension, replications, seed,
                         d_limit=_D_LIMITS[engine], n_limit=_N_LIMITS.get(engine, 2**32))
        randomizer = engine_kwargs.get("randomizer", "")
        self.randomize = (f"QMCKIT {randomizer}".strip().upper() if randomize else "FALSE")
        self._scramble = bool(randomize)
        d_engine = int(self.dvec.max()) + 1 if self.d else 0
        # One engine per replication, seeded from children of the base seed (derived
        # without spawning from it, so spawn() still hands out its own children).
        base = self._base_seed
        self._engines = []
        for r in range(self.replications):
            child = np.random.SeedSequence(base.entropy,
                                           spawn_key=tuple(base.spawn_key) + (0x51C, r))
            self._engines.append(
                _ENGINES[engine](d_engine, scramble=self._scramble,
                                 rng=np.random.default_rng(child), **self.engine_kwargs)
            )

    def _gen_samples(self, n_min, n_max, return_binary, warn):
        if return_binary:
            raise ParameterError("QMCKit has no binary (integer) representation")
        n = n_max - n_min
        x = np.empty((self.replications, n, self.d))
        with warnings.catch_warnings():
            if not warn:
                warnings.simplefilter("ignore")
            for r, e in enumerate(self._engines):
                e.reset()
                e.fast_forward(n_min)
                pts = e.random(n)
                x[r] = pts[:, self.dvec]
        return x

    def _spawn(self, child_seed, dimension):
        return QMCKit(dimension=dimension,
                      replications=None if self.no_replications else self.replications,
                      seed=child_seed, engine=self.engine, randomize=self._scramble,
                      **self.engine_kwargs)
