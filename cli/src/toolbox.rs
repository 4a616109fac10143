//! The lattice, Kronecker and Faure samplers of `qmckit points` (and so of `convergence`),
//! and `qmckit tvalue faure`.

use std::path::Path;

use qmckit::Sampler;
use qmckit::analysis::tvalue::t_value_block;
use qmckit::digital::{DigitalNetB, MAX_BASE, is_prime};
use qmckit::lattice::kronecker::Kronecker;
use qmckit::lattice::{KUO_33002, Rank1Lattice, korobov, parse_lattice};
use qmckit::randomize::digits::DigitScramble;
use qmckit::randomize::{CranleyPatterson, Scrambled, Tent};
use qmckit::work::Budget;

use super::Failure;
use super::spec::{SamplerName, ScrambleName, Spec, value_name};

/// Largest generating-vector file read (bytes): 9125 dimensions take 60 KiB.
const MAX_VECTOR_FILE: u64 = 64 << 20;

/// The sampler `spec` names, for `lattice`, `kronecker` and `faure`.
pub fn build(spec: &Spec) -> Result<Box<dyn Sampler>, Failure> {
    let d = spec.sampler.dims(spec.d);
    if d == 0 {
        return Err(Failure::usage("-d must be at least 1"));
    }
    match spec.sampler {
        SamplerName::Faure => faure(spec, d),
        SamplerName::Kronecker => shifted(Kronecker::r_d(d)?, spec),
        _ => lattice(spec, d),
    }
}

/// The lattice: Kuo's vector, a vector file (`--vector`) or Korobov's (`--korobov`), in
/// radical-inverse order, or of `--total` points in linear order.
fn lattice(spec: &Spec, d: usize) -> Result<Box<dyn Sampler>, Failure> {
    if spec.korobov.is_some() && spec.vector.is_some() {
        return Err(Failure::usage("--korobov and --vector exclude each other"));
    }
    if let Some(a) = spec.korobov {
        let Some(n) = spec.total else {
            return Err(Failure::usage(
                "--korobov needs the number of points of the rule: pass --total N",
            ));
        };
        let mut z = qmckit::size::vec_zeroed(d)?;
        korobov(a, n, &mut z)?;
        return shifted(Rank1Lattice::linear(z, n)?, spec);
    }
    if let Some(path) = &spec.vector {
        let (z, modulus) = read_vector(path, d)?;
        return match (spec.total, modulus) {
            (Some(n), _) => shifted(Rank1Lattice::linear(z, n)?, spec),
            (None, Some(n)) if n.is_power_of_two() => {
                shifted(Rank1Lattice::extensible(z, n.trailing_zeros())?, spec)
            }
            (None, Some(n)) => shifted(Rank1Lattice::linear(z, n)?, spec),
            (None, None) => Err(Failure::usage(format!(
                "{}: the file does not name its modulus; pass --total N",
                path.display()
            ))),
        };
    }
    if d > KUO_33002.len() {
        return Err(Failure::usage(format!(
            "lattice: the built-in vector has {} dimensions, -d is {d} (use --vector FILE)",
            KUO_33002.len()
        )));
    }
    let z = KUO_33002.get(..d).unwrap_or(&[]);
    match spec.total {
        Some(n) => shifted(Rank1Lattice::linear(z, n)?, spec),
        None => shifted(Rank1Lattice::kuo(d)?, spec),
    }
}

/// The first `d` components of the vector in `path` and its modulus.
fn read_vector(path: &Path, d: usize) -> Result<(Vec<u32>, Option<u64>), Failure> {
    let shown = path.display();
    let limits = super::input::Limits {
        bytes: MAX_VECTOR_FILE,
        line: 1 << 16,
        option: "--vector",
        records: u64::MAX,
    };
    let file = path.to_string_lossy();
    let (_, bytes) = super::input::read_bounded(Some(&file), limits)?;
    let text = String::from_utf8(bytes)
        .map_err(|e| Failure::usage(format!("--vector {shown}: not UTF-8 text ({e})")))?;
    let mut z = qmckit::size::vec_zeroed(d)?;
    let info = parse_lattice(&text, &mut z).map_err(|e| Failure::usage(format!("{shown}: {e}")))?;
    if info.read < d {
        return Err(Failure::usage(format!(
            "{shown} has {} components, -d asks for {d}",
            info.read
        )));
    }
    Ok((z, info.modulus))
}

/// `s` randomized by `--scramble`: none, a random shift (`shift`, `rotate`) or a shift then
/// the tent transform (`shift-tent`).
fn shifted<S: Sampler + 'static>(s: S, spec: &Spec) -> Result<Box<dyn Sampler>, Failure> {
    let seed = spec.seed;
    Ok(match spec.scramble {
        ScrambleName::None => Box::new(s),
        ScrambleName::Shift | ScrambleName::Rotate => {
            Box::new(Scrambled::new(s, CranleyPatterson::new(seed)))
        }
        ScrambleName::ShiftTent => Box::new(Scrambled::new(s, (CranleyPatterson::new(seed), Tent))),
        other => {
            return Err(Failure::usage(format!(
                "--scramble {} does not apply to {} (shift, shift-tent or rotate do)",
                value_name(&other),
                value_name(&spec.sampler)
            )));
        }
    })
}

/// The smallest prime `>= max(d, 2)`, Faure's default base.
fn faure_base(d: usize) -> u32 {
    let mut b = u32::try_from(d.max(2)).unwrap_or(u32::MAX);
    while !is_prime(b) && b < MAX_BASE {
        b += 1;
    }
    b
}

/// Faure's sequence in `--base` (default the smallest prime `>= d`), digit-scrambled.
fn faure_net(
    base: Option<u32>,
    d: usize,
    scramble: ScrambleName,
    seed: u64,
) -> Result<DigitalNetB<Vec<u16>>, Failure> {
    if d as u64 > MAX_BASE as u64 {
        return Err(Failure::usage(format!(
            "faure: -d {d} needs a prime base of at least {d}; at most {MAX_BASE} is supported"
        )));
    }
    let base = base.unwrap_or_else(|| faure_base(d));
    if !is_prime(base) || (d as u64) > base as u64 || base > MAX_BASE {
        return Err(Failure::usage(format!(
            "faure: --base {base} must be a prime of at least d = {d} (and at most {MAX_BASE})"
        )));
    }
    let digits = match scramble {
        ScrambleName::None => DigitScramble::None,
        ScrambleName::Owen => DigitScramble::Owen(seed),
        ScrambleName::Perm => DigitScramble::Permutations(seed),
        ScrambleName::Faure => DigitScramble::Faure,
        other => {
            return Err(Failure::usage(format!(
                "--scramble {} does not apply to faure (owen, perm and faure do: base-b digit \
                 scrambles)",
                value_name(&other)
            )));
        }
    };
    Ok(DigitalNetB::faure(base, d)?.with_scramble(digits))
}

fn faure(spec: &Spec, d: usize) -> Result<Box<dyn Sampler>, Failure> {
    let base = (spec.base != 0).then_some(spec.base);
    Ok(Box::new(faure_net(base, d, spec.scramble, spec.seed)?))
}

/// `qmckit tvalue faure`: the t-value of the first `b^m` points, counted exactly.
pub fn tvalue_faure(
    m: u32,
    d: usize,
    base: Option<u32>,
    scramble: ScrambleName,
    seed: u64,
    budget: &Budget,
) -> Result<(u32, u32), Failure> {
    let net = faure_net(base, d, scramble, seed)?;
    let b = net.base();
    match (b as u64).checked_pow(m) {
        Some(n) if n <= 1 << 32 => {}
        _ => {
            return Err(Failure::usage(format!(
                "-m {m}: {b}^{m} points do not fit in 32-bit indices"
            )));
        }
    }
    let t = super::progress::with_spinner("t-value (counting in base b)", || {
        t_value_block(&net, 0, m, budget)
    })?;
    Ok((t, b))
}
