//! Vectors of the pixel samplers (ZSobol, PaddedSobol, image-plane Sobol') and PMJ02, part
//! of `vectors.rs` (printed on the host and on every board, then diffed).

use core::fmt::{self, Write};
use core::hint::black_box;

use qmckit::Sampler;
use qmckit::pixel::{ImageSobol, PaddedSobol, PixelSampler, Randomization, ZSobol};
use qmckit::pmj::{Pmj02, fill};

use super::{Digest, Res};

const RANDOMIZATIONS: [(&str, Randomization); 4] = [
    ("none", Randomization::None),
    ("xor", Randomization::PermuteDigits),
    ("fastowen", Randomization::FastOwen),
    ("owen", Randomization::Owen),
];

/// One pixel sample: `<name> (x,y) i d: index get1d get2d f32-bits`.
fn one<W: Write, S: PixelSampler>(out: &mut W, name: &str, s: &S, q: [u32; 4]) -> fmt::Result {
    let [x, y, i, d] = q.map(black_box);
    let (index, v, [a, b], f) = match s.start_pixel_sample(x, y, i) {
        Ok(h) => {
            let h = h.with_dimension(d as usize);
            let index = h.sample_index().unwrap_or(u64::MAX);
            let (mut one, mut two, mut f32s) = (h, h, h);
            (
                index,
                one.get_1d(),
                two.get_2d(),
                f32s.get_1d_f32().to_bits(),
            )
        }
        Err(_) => (u64::MAX - 1, 0, [0, 0], 0),
    };
    writeln!(
        out,
        "{name} ({x},{y}) i{i} d{d}: {index:x} {v:08x} {a:08x} {b:08x} f{f:08x}"
    )
}

/// The pixel samplers: single samples, then a digest of a 32x32 image at 16 spp.
pub fn pixel<W: Write>(out: &mut W) -> fmt::Result {
    for (rname, r) in RANDOMIZATIONS {
        let seed = black_box(0u64);
        if let Ok(z) = ZSobol::new(black_box(16), 9, 4, r, seed) {
            for q in [[1, 0, 3, 0], [7, 8, 0, 5], [15, 4, 2, 1]] {
                one(out, &format_name("zsobol", rname), &z, q)?;
            }
        }
        if let Ok(p) = PaddedSobol::new(black_box(16), 16, 16, r, seed) {
            one(out, &format_name("padded", rname), &p, [3, 5, 5, 2])?;
        }
        if let Ok(s) = ImageSobol::new(black_box(16), 9, 4, r, seed) {
            one(out, &format_name("sobol", rname), &s, [3, 5, 2, 4])?;
        }
    }
    // A 4K image at 1024 spp: Morton indices past 2^32.
    if let Ok(z) = ZSobol::new(black_box(3840), 2160, 1024, Randomization::FastOwen, 3) {
        one(out, "zsobol-4k", &z, [3839, 2159, 1023, 0])?;
    }
    if let Ok(z) = ZSobol::new(black_box(32), 32, 16, Randomization::FastOwen, 1) {
        let mut d = Digest::new();
        for y in 0..32 {
            for x in 0..32 {
                for i in 0..16 {
                    if let Ok(h) = z.start_pixel_sample(x, y, i) {
                        let mut h = h.with_dimension(black_box(0));
                        d.push_all(&h.get_2d());
                        d.push(h.get_1d());
                    }
                }
            }
        }
        writeln!(out, "zsobol 32x32x16 digest {d}")?;
        // The same values through the prepared pixel-and-dimension path.
        let mut d = Digest::new();
        for y in 0..32 {
            for x in 0..32 {
                if let (Ok(d0), Ok(d2)) = (
                    z.pixel_dimension(x, y, black_box(0)),
                    z.pixel_dimension(x, y, 2),
                ) {
                    for i in 0..16 {
                        d.push_all(&d0.get_2d(i));
                        d.push(d2.get_1d(i));
                    }
                }
            }
        }
        writeln!(out, "zsobol 32x32x16 digest {d} (prepared)")?;
    }
    writeln!(
        out,
        "zsobol spp 3: {}",
        Res(ZSobol::new(4, 4, black_box(3), Randomization::None, 0).map(|_| 0))
    )
}

/// A short name without allocation: `kind-randomization` in a fixed buffer.
fn format_name(kind: &str, r: &str) -> Name {
    let mut n = Name {
        buf: [0; 24],
        len: 0,
    };
    for part in [kind, "-", r] {
        for &c in part.as_bytes() {
            if n.len < n.buf.len() {
                n.buf[n.len] = c;
                n.len += 1;
            }
        }
    }
    n
}

/// The text of [`format_name`].
struct Name {
    buf: [u8; 24],
    len: usize,
}

impl core::ops::Deref for Name {
    type Target = str;
    fn deref(&self) -> &str {
        core::str::from_utf8(&self.buf[..self.len]).unwrap_or("?")
    }
}

/// PMJ02: a buffer fill, random access deep in the sequence, and a digest.
pub fn pmj<W: Write>(out: &mut W) -> fmt::Result {
    let mut pts = [[0u32; 2]; 64];
    if fill(black_box(5), &mut pts).is_ok() {
        for k in [0usize, 1, 2, 3, 17, 63] {
            writeln!(
                out,
                "pmj02 seed 5 #{k}: {:08x} {:08x}",
                pts[k][0], pts[k][1]
            )?;
        }
    }
    let p = Pmj02::new(black_box(5));
    let mut d = Digest::new();
    for k in 0..4096u32 {
        d.push(p.sample(k, 0).unwrap_or(0));
        d.push(p.sample(k, 1).unwrap_or(0));
    }
    writeln!(out, "pmj02 seed 5 4096 digest {d}")?;
    for k in [1_000_000u32, u32::MAX] {
        let x = Res(p.sample(black_box(k), 0));
        let y = Res(p.sample(black_box(k), 1));
        writeln!(out, "pmj02 seed 5 #{k}: {x} {y}")?;
    }
    writeln!(out, "pmj02 dim 2: {}", Res(p.sample(0, black_box(2))))?;
    pmj02bn(out)
}

/// PMJ02BN (PMJ02 spread by nested flips) in caller storage: 128 points (1 KiB, and
/// 4 KiB of workspace: the micro:bit has 16 KiB of RAM), a few points and a digest; Christensen's best-candidate construction, 8 candidates, likewise.
fn pmj02bn<W: Write>(out: &mut W) -> fmt::Result {
    use qmckit::pmj::{bn, christensen};
    use qmckit::work::Budget;
    let unlimited = &Budget::UNLIMITED;
    let mut pts = [[0u32; 2]; 128];
    let mut work = [0u32; 1016];
    match christensen::fill(black_box(5), 8, &mut pts, &mut work, unlimited) {
        Ok(()) => {
            let mut d = Digest::new();
            pts.iter().for_each(|q| d.push_all(q));
            writeln!(out, "pmj02 best candidate seed 5 128 digest {d}")?;
        }
        Err(_) => writeln!(out, "pmj02 best candidate: error")?,
    }
    match bn::fill(black_box(5), &mut pts, &mut work, unlimited) {
        Ok(()) => {
            for k in [0usize, 1, 2, 3, 17, 127] {
                writeln!(
                    out,
                    "pmj02bn seed 5 #{k}: {:08x} {:08x}",
                    pts[k][0], pts[k][1]
                )?;
            }
            let mut d = Digest::new();
            pts.iter().for_each(|q| d.push_all(q));
            writeln!(out, "pmj02bn seed 5 128 digest {d}")?;
        }
        Err(_) => writeln!(out, "pmj02bn: error")?,
    }
    writeln!(
        out,
        "pmj02bn short work: {}",
        Res(bn::fill(5, &mut pts, &mut work[..10], unlimited).map(|_| 0))
    )
}
