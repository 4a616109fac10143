"""qmckit: quasi-Monte Carlo sampling in Rust, with SciPy's interface.

The engines subclass :class:`scipy.stats.qmc.QMCEngine` and take SciPy's arguments, so
they drop into code written for ``scipy.stats.qmc`` (including
``scipy.integrate.qmc_quad``)::

    import qmckit
    engine = qmckit.Sobol(d=8, rng=42)          # Owen-scrambled Sobol' (hash-based)
    x = engine.random_base2(16)
    qmckit.discrepancy(x, method="CD")

Unscrambled ``Sobol`` and ``Halton``, ``Sobol(randomizer="lms")`` and
``Halton(randomizer="scipy-perm")`` give the same points as SciPy's engines.
"""

from ._qmckit import __version__
from ._engines import (
    Faure,
    Halton,
    Kronecker,
    Lattice,
    PMJ02,
    PMJ02BN,
    PoissonDisk,
    Sobol,
)
from ._lhs import LatinHypercube
from ._discrepancy import discrepancy

__all__ = [
    "Sobol",
    "Halton",
    "LatinHypercube",
    "Lattice",
    "Kronecker",
    "Faure",
    "PMJ02",
    "PMJ02BN",
    "PoissonDisk",
    "discrepancy",
    "__version__",
]
