//! pbrt-v4's `Hash` of pixel-sampler inputs with the crate's 64-bit seeds: bit-identical
//! to pbrt for a seed below `2^32` (its `int` seed), all 64 bits hashed above.

/// pbrt's `Hash(a, seed)` with a 64-bit seed: MurmurHash64A of the 8 bytes `(a, seed)` for
/// `seed < 2^32` (pbrt's `int` seed, bit-identical), of the 12 bytes `(a, seed as u64)`
/// above, so distinct seeds stay distinct.
#[inline]
pub(crate) const fn seed_hash2(a: u32, seed: u64) -> u64 {
    if seed >> 32 == 0 {
        return crate::hash::pbrt::hash2(a, seed as u32);
    }
    let (a, s) = (a.to_le_bytes(), seed.to_le_bytes());
    let b = [
        a[0], a[1], a[2], a[3], s[0], s[1], s[2], s[3], s[4], s[5], s[6], s[7],
    ];
    crate::hash::pbrt::murmur_hash64a(&b, 0)
}

/// pbrt's `Hash(p, dim, seed)` with a 64-bit seed: [`hash4`](crate::hash::pbrt::hash4) of
/// the 16 bytes for `seed < 2^32`, MurmurHash64A of the 20 bytes `(x, y, dim, seed as
/// u64)` above. `dim` is the dimension's low 32 bits (pbrt's `int`).
#[inline]
pub(crate) const fn seed_hash4(x: u32, y: u32, dim: usize, seed: u64) -> u64 {
    let d = dim as u32;
    if seed >> 32 == 0 {
        return crate::hash::pbrt::hash4(x, y, d, seed as u32);
    }
    let (x, y, d, s) = (
        x.to_le_bytes(),
        y.to_le_bytes(),
        d.to_le_bytes(),
        seed.to_le_bytes(),
    );
    let b = [
        x[0], x[1], x[2], x[3], y[0], y[1], y[2], y[3], d[0], d[1], d[2], d[3], s[0], s[1], s[2],
        s[3], s[4], s[5], s[6], s[7],
    ];
    crate::hash::pbrt::murmur_hash64a(&b, 0)
}
