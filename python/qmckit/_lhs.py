"""Latin hypercube designs with SciPy's interface: strength 1 from qmckit's sampler,
strength 2 (orthogonal-array LHS) drawn here with the engine's ``rng``."""

from __future__ import annotations

import numpy as np
from scipy._lib._util import _transition_to_rng

from . import _qmckit
from ._engines import _INDEX_LIMIT, _NativeEngine, _draw_seed

__all__ = ["LatinHypercube"]


class LatinHypercube(_NativeEngine):
    """Latin hypercube sampling, as :class:`scipy.stats.qmc.LatinHypercube`: every call
    draws a new design of ``n`` points (one point in each of the ``n`` slabs of every
    axis; centered in its cell when ``scramble=False``).

    ``strength=1``: from a qmckit seed drawn from ``rng``.

    ``strength=2``: an orthogonal-array-based LHS (Tang 1993; Owen 1992): ``n = p**2``
    with ``p`` prime and ``d <= p + 1`` (``ValueError`` otherwise, as SciPy). Bose's
    orthogonal array OA(p^2, p + 1, p, 2) has rows ``(a, b)`` of ``Z_p^2`` and columns
    ``a`` and ``b + c a mod p`` (``c = 0 .. p - 1``): in any two columns every pair of
    symbols occurs once. Each column's symbols are relabelled by a random permutation,
    and the ``p`` rows holding symbol ``s`` get the sub-slabs ``s p .. s p + p - 1`` in a
    random order: a Latin hypercube whose every 2-D projection puts one point in each
    cell of the ``p x p`` grid. Drawn with ``rng`` (numpy), ``O(n d)``."""

    @_transition_to_rng("seed", replace_doc=False)
    def __init__(self, d, *, scramble=True, strength=1, optimization=None, rng=None):
        self._init_quad = {
            "d": d,
            "scramble": True,
            "strength": strength,
            "optimization": optimization,
        }
        super()._initialize(d=d, rng=rng, optimization=optimization)
        if strength not in (1, 2):
            raise ValueError(
                f"{strength!r} is not a valid strength. It must be one of {{1, 2}}"
            )
        self.scramble = scramble
        self.strength = strength

    def _check_n(self, n):
        if n > _INDEX_LIMIT:
            raise ValueError(f"At most 2**32 points a design (qmckit), got n={n}")
        if self.strength == 2:
            _oa_order(n, self.d)

    def _fill(self, out, workers):
        n = out.shape[0]
        if self.strength == 2:
            return self._fill_oa(out)
        if n == 0 or self.d == 0:
            return out
        native = _qmckit.latin_hypercube(n, self.d, _draw_seed(self.rng))
        if self.scramble:
            native.fill(0, out, workers)
        else:
            u = np.empty((n, self.d), dtype=np.uint32)
            native.fill(0, u, workers)
            slab = (u.astype(np.uint64) * np.uint64(n)) >> np.uint64(32)
            np.divide(slab + 0.5, n, out=out)
        return out

    def _fill_oa(self, out):
        """The strength-2 design (see the class): ``n = p**2`` points into ``out``."""
        n = out.shape[0]
        p = _oa_order(n, self.d)
        if self.d == 0:
            return out
        a, b = np.divmod(np.arange(n), p)
        for j in range(self.d):
            # Column j of Bose's array: a, then b + (j - 1) a mod p.
            col = a if j == 0 else (b + (j - 1) * a) % p
            sym = self.rng.permutation(p)[col]
            # The p rows of each symbol, in row order, take a random order of its p
            # sub-slabs.
            rows = np.argsort(sym, kind="stable")
            sub = np.argsort(self.rng.uniform(size=(p, p)), axis=1).ravel()
            slab = np.empty(n, dtype=np.int64)
            slab[rows] = sym[rows] * p + sub
            u = self.rng.uniform(size=n) if self.scramble else 0.5
            out[:, j] = (slab + u) / n
        return out

    def fast_forward(self, n):
        """As SciPy: draws (and discards) ``n`` points, advancing ``rng``."""
        self.random(n)
        return self


def _is_prime(p: int) -> bool:
    return p >= 2 and all(p % q for q in range(2, int(p**0.5) + 1))


def _oa_order(n: int, d: int) -> int:
    """``p`` of a strength-2 design of ``n = p**2`` points in ``d <= p + 1``
    dimensions, or ``ValueError`` (SciPy's messages)."""
    p = int(np.sqrt(n))
    while p * p > n:
        p -= 1
    while (p + 1) * (p + 1) <= n:
        p += 1
    if p * p != n or not _is_prime(p):
        # The squares of the two largest primes up to p (of 2 and 3 below p = 3).
        primes = ([2, 3] + [q for q in range(4, p + 1) if _is_prime(q)])[-2:]
        raise ValueError(
            "n is not the square of a prime number. Close values are "
            f"{np.array(primes) ** 2}"
        )
    if d > p + 1:
        raise ValueError("n is too small for d. Must be n > (d-1)**2")
    return p
