//! The nested hashes of hash-based Owen scrambling: bijections of a bit-reversed 0.32
//! fraction in which output bit `k` depends only on input bits `<= k`, so that, read back in
//! the un-reversed order, each bit is flipped by a function of the bits above it.

/// The Laine–Karras permutation (Laine & Karras 2011, as used by Burley 2020, "Practical
/// hash-based Owen scrambling") on a *bit-reversed* 0.32 fraction: `x + seed`, then four
/// `x ^= x * c` steps with even constants. Bit `k` of the output depends only on bits `<= k`
/// of the input, so in the un-reversed domain it is a nested scramble, and it is a bijection.
#[inline]
pub const fn laine_karras(x: u32, seed: u32) -> u32 {
    let mut x = x.wrapping_add(seed);
    x ^= x.wrapping_mul(0x6C50_B47C);
    x ^= x.wrapping_mul(0xB82F_1E52);
    x ^= x.wrapping_mul(0xC7AF_E638);
    x ^= x.wrapping_mul(0x8D22_F6E6);
    x
}

/// Vegdahl's improved Laine–Karras-style hash (2021, "Building a better LK hash"), on a
/// bit-reversed 0.32 fraction: better avalanche between the bits, same nested structure
/// (multiplications by odd numbers and `x ^= x * even`), a bijection.
#[inline]
pub const fn vegdahl(x: u32, seed: u32) -> u32 {
    vegdahl_prepared(x, seed, vegdahl_multiplier(seed))
}

/// The odd multiplier of [`vegdahl`] for `seed`, `(seed >> 16) | 1`: the part of the hash
/// that depends on the seed alone, for loops hashing many values with one seed.
#[inline]
pub(crate) const fn vegdahl_multiplier(seed: u32) -> u32 {
    (seed >> 16) | 1
}

/// [`vegdahl`] with its seed-only part given: `vegdahl(x, seed) == vegdahl_prepared(x, seed,
/// vegdahl_multiplier(seed))` (the same steps; `vegdahl` is this with the multiplier
/// computed).
#[inline]
pub(crate) const fn vegdahl_prepared(x: u32, seed: u32, multiplier: u32) -> u32 {
    let mut x = x ^ x.wrapping_mul(0x3D20_ADEA);
    x = x.wrapping_add(seed);
    x = x.wrapping_mul(multiplier);
    x ^= x.wrapping_mul(0x0552_6C56);
    x ^= x.wrapping_mul(0x53A2_2864);
    x
}
