//! `qmckit tvalue faure`: Faure's net counted in its base (the samplers themselves are the
//! catalog's, `qmckit::catalog::build`).

use qmckit::analysis::tvalue::t_value_block;
use qmckit::digital::{DigitalNetB, MAX_BASE, is_prime};
use qmckit::randomize::digits::DigitScramble;
use qmckit::work::Budget;

use super::Failure;
use qmckit::catalog::RandomizerKind;

use super::points::ScrambleName;

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
    let digits = match scramble.kind {
        RandomizerKind::None => DigitScramble::None,
        RandomizerKind::Owen => DigitScramble::Owen(seed),
        RandomizerKind::Perm => DigitScramble::Permutations(seed),
        RandomizerKind::Faure => DigitScramble::Faure,
        _ => {
            return Err(Failure::usage(format!(
                "--scramble {} does not apply to faure (owen, perm and faure do: base-b digit \
                 scrambles)",
                scramble.name
            )));
        }
    };
    Ok(DigitalNetB::faure(base, d)?.with_scramble(digits))
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
