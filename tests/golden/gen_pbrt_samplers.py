#!/usr/bin/env python3
"""Golden values for qmckit's pixel samplers, from an independent Python reading of pbrt-v4's
definitions (src/pbrt/samplers.h, util/lowdiscrepancy.h, util/hash.h, util/math.h).

Everything here is written from the definitions, integer by integer, with Python's
unbounded integers masked to the C widths (u32, u64):

  * MixBits, MurmurHash64A (seed 0) of the packed little-endian arguments (`Hash`),
    PermutationElement (Kensler 2013), ReverseBits32;
  * the randomizers: none, BinaryPermuteScrambler (XOR), FastOwenScrambler, OwenScrambler;
  * Sobol' dimension 0 (bit reversal) and 1 (Pascal matrix, column k+1 = c ^ (c >> 1)), and
    dimensions >= 2 from Joe & Kuo's new-joe-kuo-6.21201 by their recurrence;
  * ZSobolSampler::GetSampleIndex / Get1D / Get2D, PaddedSobolSampler, SobolSampler with
    SobolIntervalToIndex computed by BRUTE-FORCE SEARCH (the i-th index of the frame whose
    first two coordinates fall in the pixel), not by pbrt's tables;
  * floats as pbrt makes them: min(float32(v) * 2^-32, 0x1.fffffep-1).

It first asserts the check values pbrt-v4 gives (16x9 image, seed 0, FastOwen), then writes
pbrt_samplers.txt. With a pbrt-v4 checkout as first argument it also checks the Joe-Kuo
columns against pbrt's SobolMatrices32 (src/pbrt/util/sobolmatrices.cpp).

Run: `python3 tests/golden/gen_pbrt_samplers.py [PBRT_V4_DIR]` (numpy). cargo test reads only
the committed output.
"""
import re
import struct
import sys
from pathlib import Path

import numpy as np

HERE = Path(__file__).resolve().parent
ROOT = HERE.parent.parent
M32 = 0xFFFFFFFF
M64 = 0xFFFFFFFFFFFFFFFF


def mix_bits(v):
    v &= M64
    v ^= v >> 31
    v = (v * 0x7FB5D329728EA185) & M64
    v ^= v >> 27
    v = (v * 0x81DADEF4BC2DD44D) & M64
    v ^= v >> 33
    return v


def murmur64a(data, seed=0):
    m, r = 0xC6A4A7935BD1E995, 47
    n = len(data)
    h = (seed ^ (n * m)) & M64
    full = n // 8 * 8
    for o in range(0, full, 8):
        k = int.from_bytes(data[o:o + 8], "little")
        k = (k * m) & M64
        k ^= k >> r
        k = (k * m) & M64
        h ^= k
        h = (h * m) & M64
    rest = data[full:]
    if rest:
        for j in reversed(range(len(rest))):
            h ^= rest[j] << (8 * j)
        h = (h * m) & M64
    h ^= h >> r
    h = (h * m) & M64
    h ^= h >> r
    return h


def hash_ints(*args):
    """pbrt's Hash(int, int, ...): MurmurHash64A of the packed 32-bit ints."""
    return murmur64a(b"".join(struct.pack("<i", a) for a in args))


def rev32(v):
    return int(f"{v & M32:032b}"[::-1], 2)


def permutation_element(i, l, p):
    w = (l - 1) & M32
    for s in (1, 2, 4, 8, 16):
        w |= w >> s
    while True:
        i ^= p
        i = (i * 0xE170893D) & M32
        i ^= p >> 16
        i ^= (i & w) >> 4
        i ^= p >> 8
        i = (i * 0x0929EB3F) & M32
        i ^= p >> 23
        i ^= (i & w) >> 1
        i = (i * (1 | p >> 27)) & M32
        i = (i * 0x6935FA69) & M32
        i ^= (i & w) >> 11
        i = (i * 0x74DCB303) & M32
        i ^= (i & w) >> 2
        i = (i * 0x9E501CC3) & M32
        i ^= (i & w) >> 2
        i = (i * 0xC860A3DF) & M32
        i &= w
        i ^= i >> 5
        if i < l:
            return ((i + p) & M32) % l  # u32 addition, as in C


def fast_owen(v, seed):
    v = rev32(v)
    v ^= (v * 0x3D20ADEA) & M32
    v = (v + seed) & M32
    v = (v * ((seed >> 16) | 1)) & M32
    v ^= (v * 0x05526C56) & M32
    v ^= (v * 0x53A22864) & M32
    return rev32(v)


def owen(v, seed):
    if seed & 1:
        v ^= 1 << 31
    for b in range(1, 32):
        mask = (M32 << (32 - b)) & M32
        if mix_bits((v & mask) ^ seed) & M32 & (1 << b):
            v ^= 1 << (31 - b)
    return v


RANDOMIZERS = {
    "none": lambda v, s: v,
    "xor": lambda v, s: v ^ s,
    "fastowen": fast_owen,
    "owen": owen,
}


def joe_kuo_columns(ndims):
    """32-bit generator columns of Sobol' dims 0..ndims-1 (dim 0 = van der Corput)."""
    cols = [[1 << (31 - k) for k in range(32)]]
    lines = (ROOT / "tables" / "new-joe-kuo-6.21201").read_text().split("\n")[1:]
    for line in lines[: ndims - 1]:
        f = [int(t) for t in line.split()]
        s, a, mm = f[1], f[2], f[3:]
        v = [mm[k] << (31 - k) for k in range(s)]
        for k in range(s, 32):
            x = v[k - s] ^ (v[k - s] >> s)
            for l in range(1, s):
                if (a >> (s - 1 - l)) & 1:
                    x ^= v[k - l]
            v.append(x)
        cols.append(v)
    return cols


SOBOL_DIMS = 8
COLS = joe_kuo_columns(SOBOL_DIMS)


def pascal_column(k):
    c = 1 << 31
    for _ in range(k):
        c ^= c >> 1
    return c


def sobol(a, dim):
    """Unscrambled Sobol' value (u32) of index a (dims 0 and 1 for any 64-bit a)."""
    v = 0
    k = 0
    while a:
        if a & 1:
            if dim == 0:
                v ^= (1 << (31 - k)) if k < 32 else 0
            elif dim == 1:
                v ^= pascal_column(k)
            else:
                assert k < 32, "dims >= 2 only for 32-bit indices here"
                v ^= COLS[dim][k]
        a >>= 1
        k += 1
    return v


def to_f32_bits(v):
    f = np.float32(v) * np.float32(2.0 ** -32)
    one_minus = np.float32(np.nextafter(np.float32(1), np.float32(0)))
    f = min(f, one_minus)
    return struct.unpack("<I", struct.pack("<f", f))[0]


def f32_of_bits(b):
    return struct.unpack("<f", struct.pack("<I", b))[0]


def round_up_pow2(v):
    p = 1
    while p < v:
        p <<= 1
    return p


def log2_int(v):
    return v.bit_length() - 1


def spread(x):
    x &= M32
    out = 0
    for k in range(32):
        out |= ((x >> k) & 1) << (2 * k)
    return out


def morton2(x, y):
    return (spread(y) << 1) | spread(x)


def perm24():
    """pbrt's 24 permutations of (0,1,2,3), in pbrt's order, by three swaps."""
    out = []
    for a in range(4):
        for b in range(3):
            for c in range(2):
                p = [0, 1, 2, 3]
                p[0], p[a] = p[a], p[0]
                p[1], p[1 + b] = p[1 + b], p[1]
                p[2], p[2 + c] = p[2 + c], p[2]
                out.append(p)
    return out


PERM24 = perm24()
# pbrt's table, typed in from samplers.h, to check the rule above.
PBRT_PERM24_FIRST = [[0, 1, 2, 3], [0, 1, 3, 2], [0, 2, 1, 3], [0, 2, 3, 1], [0, 3, 2, 1],
                     [0, 3, 1, 2], [1, 0, 2, 3], [1, 0, 3, 2], [1, 2, 0, 3], [1, 2, 3, 0],
                     [1, 3, 2, 0], [1, 3, 0, 2], [2, 1, 0, 3], [2, 1, 3, 0], [2, 0, 1, 3],
                     [2, 0, 3, 1], [2, 3, 0, 1], [2, 3, 1, 0], [3, 1, 2, 0], [3, 1, 0, 2],
                     [3, 2, 1, 0], [3, 2, 0, 1], [3, 0, 2, 1], [3, 0, 1, 2]]


class ZSobol:
    def __init__(self, spp, w, h, rand, seed):
        self.log2spp = log2_int(spp)
        res = round_up_pow2(max(w, h))
        self.digits = log2_int(res) + (self.log2spp + 1) // 2
        self.rand, self.seed = RANDOMIZERS[rand], seed

    def morton(self, px, py, i):
        return ((morton2(px, py) << self.log2spp) | i) & M64

    def index(self, morton, dim):
        salt = (0x55555555 * dim) & M32
        odd = self.log2spp & 1
        idx = 0
        for i in range(self.digits - 1, odd - 1, -1):
            shift = 2 * i - odd
            digit = (morton >> shift) & 3
            higher = morton >> (shift + 2)
            p = (mix_bits(higher ^ salt) >> 24) % 24
            idx |= PERM24[p][digit] << shift
        if odd:
            idx |= (morton & 1) ^ (mix_bits((morton >> 1) ^ salt) & 1)
        return idx

    def get(self, px, py, i, dim):
        m = self.morton(px, py, i)
        idx1 = self.index(m, dim)
        s1 = hash_ints(dim + 1, self.seed) & M32
        v1 = self.rand(sobol(idx1, 0), s1)
        idx2 = idx1  # same index: GetSampleIndex uses the current dimension
        h2 = hash_ints(dim + 2, self.seed)
        x = self.rand(sobol(idx2, 0), h2 & M32)
        y = self.rand(sobol(idx2, 1), h2 >> 32)
        return idx1, v1, x, y


class PaddedSobol:
    def __init__(self, spp, rand, seed):
        self.spp, self.rand, self.seed = spp, RANDOMIZERS[rand], seed

    def get(self, px, py, i, dim):
        h = hash_ints(px, py, dim, self.seed)
        idx = permutation_element(i, self.spp, h & M32)
        v1 = self.rand(sobol(idx, 0), h >> 32)
        x = self.rand(sobol(idx, 0), h & M32)
        y = self.rand(sobol(idx, 1), h >> 32)
        return idx, v1, x, y


class SobolSampler:
    def __init__(self, spp, w, h, rand, seed):
        self.scale = round_up_pow2(max(w, h))
        self.m = log2_int(self.scale)
        self.rand, self.seed = RANDOMIZERS[rand], seed

    def interval_to_index(self, frame, px, py):
        """Brute force: the index of frame `frame` whose point lies in pixel (px, py)."""
        m = self.m
        if m == 0:
            return frame
        base = frame << (2 * m)
        found = [k for k in range(base, base + (1 << (2 * m)))
                 if sobol(k, 0) >> (32 - m) == px and sobol(k, 1) >> (32 - m) == py]
        assert len(found) == 1
        return found[0]

    def dimension(self, idx, d):
        if self.rand is RANDOMIZERS["none"]:
            return sobol(idx, d)
        return self.rand(sobol(idx, d), hash_ints(d, self.seed) & M32)

    def get(self, px, py, i, dim):
        idx = self.interval_to_index(i, px, py)
        d = max(2, dim)
        v1 = self.dimension(idx, d)
        x, y = self.dimension(idx, d), self.dimension(idx, d + 1)
        # GetPixel2D: unscrambled dims 0, 1, as floats scaled into the pixel.
        u = [f32_of_bits(to_f32_bits(sobol(idx, 0))), f32_of_bits(to_f32_bits(sobol(idx, 1)))]
        one_minus = np.float32(np.nextafter(np.float32(1), np.float32(0)))
        pix = []
        for c, p in zip(u, (px, py)):
            t = np.float32(np.float32(c) * np.float32(self.scale) - np.float32(p))
            t = min(max(t, np.float32(0)), one_minus)
            pix.append(struct.unpack("<I", struct.pack("<f", t))[0])
        return idx, v1, x, y, pix


def check_pbrt_values():
    assert PERM24 == PBRT_PERM24_FIRST
    assert hash_ints(0, 0) == 0x7208F7FA198A2D81
    assert hash_ints(1, 0) == 0x8FBB8D815C9E092E
    assert hash_ints(3, 7) == 0x7DDDE85469977F6A
    assert hash_ints(3, 5, 0, 0) == 0xD539D46ED3159A89
    assert mix_bits(1) == 0xCCDE22C1FAA4D20F
    assert fast_owen(0x80000000, 0x12345678) == 0x87E32B06
    assert owen(0x80000000, 0x12345678) == 0xBF7FD854
    assert permutation_element(3, 16, 0x12345678) == 12
    assert permutation_element(5, 7, 42) == 3

    def close(a_bits, want):
        got = f32_of_bits(to_f32_bits(a_bits))
        assert abs(got - want) < 5e-9, (got, want)

    z = ZSobol(1, 16, 9, "fastowen", 0)
    idx, v1, x, y = z.get(1, 0, 0, 0)
    assert idx == 1
    close(v1, 0.570228934)
    close(x, 0.702183783)
    close(y, 0.853890479)
    z = ZSobol(4, 16, 9, "fastowen", 0)
    idx, v1, _, _ = z.get(1, 0, 3, 0)
    assert idx == 4
    close(v1, 0.336978048)
    p = PaddedSobol(16, "none", 0)
    _, v1, x, y = p.get(3, 5, 0, 0)
    assert (v1, x, y) == (0x90000000, 0x90000000, 0x70000000)  # 0.5625 0.5625 0.4375
    _, _, x, y = p.get(3, 5, 1, 2)
    assert (x, y) == (0xC0000000, 0x40000000)
    _, _, x, y = p.get(3, 5, 15, 7)
    assert (x, y) == (0x10000000, 0xF0000000)
    p = PaddedSobol(16, "fastowen", 0)
    _, v1, x, y = p.get(3, 5, 0, 0)
    close(v1, 0.773123562)
    close(x, 0.172279)
    close(y, 0.043057885)
    _, v1, x, y = p.get(3, 5, 5, 2)
    close(v1, 0.537301898)
    close(x, 0.243017271)
    close(y, 0.191734999)


def check_against_pbrt_matrices(pbrt_dir):
    text = (Path(pbrt_dir) / "src/pbrt/util/sobolmatrices.cpp").read_text()
    start = text.index("SobolMatrices32[")
    vals = [int(v, 16) for v in re.findall(r"0x[0-9a-fA-F]+", text[start:text.index("};", start)])]
    for d in range(SOBOL_DIMS):
        assert vals[52 * d: 52 * d + 32] == COLS[d], d
    for k in range(52):
        assert vals[52 + k] == pascal_column(k), k
        assert vals[k] == ((1 << (31 - k)) if k < 32 else 0), k
    print(f"Sobol' columns of dims 0..{SOBOL_DIMS - 1} equal pbrt's SobolMatrices32")


def main():
    check_pbrt_values()
    if len(sys.argv) > 1:
        check_against_pbrt_matrices(sys.argv[1])
    out = []
    out.append("# pbrt-v4 pixel samplers, from tests/golden/gen_pbrt_samplers.py (pbrt's definitions")
    out.append("# re-implemented in Python). Values are u32 0.32 fractions in hex, then the f32 bits")
    out.append("# pbrt returns (min(float(v) * 2^-32, 1 - 2^-24)).")
    out.append("# zsobol W H spp seed rand px py i dim | index get1d get2d.x get2d.y | f32 bits x3")
    out.append("# padded W H spp seed rand px py i dim | index get1d get2d.x get2d.y | f32 bits x3")
    out.append("# sobol  W H spp seed rand px py i dim | index get1d get2d.x get2d.y | pixel2d f32 bits x2")
    cases = []
    for (w, h) in ((16, 9), (5, 3), (33, 17)):
        for spp in (1, 2, 4, 8, 16, 32):
            for rand in ("none", "xor", "fastowen", "owen"):
                for seed in (0, 7):
                    cases.append((w, h, spp, seed, rand))
    rng = np.random.default_rng(20261201)
    for (w, h, spp, seed, rand) in cases:
        z = ZSobol(spp, w, h, rand, seed)
        pd = PaddedSobol(spp, rand, seed)
        for _ in range(4):
            px, py = int(rng.integers(w)), int(rng.integers(h))
            i = int(rng.integers(spp))
            dim = int(rng.integers(7))
            idx, v1, x, y = z.get(px, py, i, dim)
            fb = " ".join(f"{to_f32_bits(v):08x}" for v in (v1, x, y))
            out.append(f"zsobol {w} {h} {spp} {seed} {rand} {px} {py} {i} {dim} {idx:x} "
                       f"{v1:08x} {x:08x} {y:08x} {fb}")
            idx, v1, x, y = pd.get(px, py, i, dim)
            fb = " ".join(f"{to_f32_bits(v):08x}" for v in (v1, x, y))
            out.append(f"padded {w} {h} {spp} {seed} {rand} {px} {py} {i} {dim} {idx:x} "
                       f"{v1:08x} {x:08x} {y:08x} {fb}")
            if max(w, h) <= 16:
                s = SobolSampler(spp, w, h, rand, seed)
                sdim = int(rng.integers(SOBOL_DIMS - 1))
                idx, v1, x, y, pix = s.get(px, py, i, sdim)
                out.append(f"sobol {w} {h} {spp} {seed} {rand} {px} {py} {i} {sdim} {idx:x} "
                           f"{v1:08x} {x:08x} {y:08x} {pix[0]:08x} {pix[1]:08x}")
    # A large image: ZSobol indices past 2^32 (3840x2160 at 1024 spp).
    for rand in ("none", "fastowen", "owen"):
        z = ZSobol(1024, 3840, 2160, rand, 3)
        for (px, py, i, dim) in ((3839, 2159, 1023, 0), (2048, 1000, 517, 5), (17, 2100, 3, 2)):
            idx, v1, x, y = z.get(px, py, i, dim)
            fb = " ".join(f"{to_f32_bits(v):08x}" for v in (v1, x, y))
            out.append(f"zsobol 3840 2160 1024 3 {rand} {px} {py} {i} {dim} {idx:x} "
                       f"{v1:08x} {x:08x} {y:08x} {fb}")
    (HERE / "pbrt_samplers.txt").write_text("\n".join(out) + "\n")
    print(f"wrote {len(out)} lines")


if __name__ == "__main__":
    main()
