"""Type stubs of the native layer ``qmckit._qmckit``."""

from typing import Optional, Sequence

import numpy as np
import numpy.typing as npt

__version__: str
SOBOL_MAX_DIMS: int
HALTON_MAX_DIMS: int

class NativeSampler:
    """A point generator filling caller-owned arrays in place."""

    @property
    def dims(self) -> int: ...
    @property
    def len(self) -> int: ...
    @property
    def name(self) -> str: ...
    def fill(
        self,
        start: int,
        out: npt.NDArray[np.float64] | npt.NDArray[np.uint32],
        workers: int = 1,
    ) -> None:
        """Points ``start .. start + n`` into the C-contiguous ``(n, dims)`` array
        ``out`` (float64 in [0, 1), or uint32 0.32 fractions); no copy."""

def sobol(
    d: int,
    bits: int = 30,
    randomizer: Optional[str] = None,
    seed: int = 0,
    images: Optional[npt.NDArray[np.uint32]] = None,
    shifts: Optional[npt.NDArray[np.uint32]] = None,
) -> NativeSampler: ...
def halton(d: int, randomizer: Optional[str] = None, seed: int = 0) -> NativeSampler: ...
def halton_scipy(
    bases: Sequence[int], permutations: Optional[Sequence[npt.NDArray[np.int64]]] = None
) -> NativeSampler: ...
def lattice(d: int, shift: bool = False, seed: int = 0) -> NativeSampler: ...
def kronecker(d: int, shift: bool = False, seed: int = 0) -> NativeSampler: ...
def faure(d: int, randomizer: Optional[str] = None, seed: int = 0) -> NativeSampler: ...
def latin_hypercube(n: int, d: int, seed: int) -> NativeSampler: ...
def pmj02(seed: int) -> NativeSampler: ...
def pmj02bn(n: int, seed: int) -> NativeSampler: ...
def catalog_set(
    name: str,
    n: int,
    d: Optional[int] = None,
    seed: int = 0,
    iterations: Optional[int] = None,
    torus: bool = False,
    projective: bool = False,
    temperature: Optional[float] = None,
) -> NativeSampler: ...
def poisson_disk(
    d: int, radius: float, candidates: int = 30, seed: int = 0, surface: bool = False
) -> npt.NDArray[np.float64]: ...
def discrepancy(
    sample: npt.NDArray[np.float64],
    method: str = "CD",
    iterative: bool = False,
    workers: int = 1,
) -> float: ...
