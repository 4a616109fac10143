//! Sobol' points with qmckit's exact Owen scrambling (`ExactOwen`), kept to `bits` bits:
//! the same values as `Scrambled::new(sobol, ExactOwen::new(seed))` masked to the top
//! `bits` bits, filled in batches. A fill generates whole rows of plain Sobol' points
//! (the library's batch fill), then scrambles each column with the dimension's
//! `ExactOwenTable`: the top tree levels (the flips shared by many points) tabled once a
//! fill, the others hashed a value at a time, vectorized; the levels below `bits` (masked
//! off anyway) are not hashed.

use qmckit::bits::FromFraction;
use qmckit::randomize::{ExactOwen, ExactOwenScrambler, ExactOwenTable};
use qmckit::{Sampler, Sobol};

/// Most tabled levels (a table is `2^levels` `u32`).
const MAX_LEVELS: u32 = 16;

/// Memory for all the tables of a fill, in `u32`.
const TABLE_BUDGET: usize = 1 << 22;

/// Rows a block of a fill (scrambled and converted while in cache).
const BLOCK_ROWS: usize = 2048;

/// Sobol' + exact Owen, `bits`-bit coordinates.
pub struct SobolOwen {
    sobol: Sobol,
    scramblers: Vec<ExactOwenScrambler>,
    bits: u32,
}

impl SobolOwen {
    /// `sobol` scrambled by `ExactOwen::new(seed)`, kept to `bits` (1 to 32) bits.
    pub fn new(sobol: Sobol, seed: u64, bits: u32) -> Self {
        let owen = ExactOwen::new(seed);
        let scramblers = (0..sobol.dims()).map(|d| owen.scrambler(d)).collect();
        SobolOwen {
            sobol,
            scramblers,
            bits: bits.clamp(1, 32),
        }
    }

    fn mask(&self) -> u32 {
        u32::MAX << (32 - self.bits)
    }

    /// The tables for a fill of `rows` rows: about `log2(rows)` levels (so the table costs
    /// at most about one hash a point), within [`MAX_LEVELS`] and [`TABLE_BUDGET`].
    fn tables(&self, rows: usize) -> Vec<ExactOwenTable> {
        let dims = self.scramblers.len().max(1);
        let by_rows = usize::BITS - rows.max(1).leading_zeros();
        let by_budget = usize::BITS - (TABLE_BUDGET / dims).max(1).leading_zeros() - 1;
        let levels = by_rows.min(by_budget).min(MAX_LEVELS).min(self.bits).max(1);
        self.scramblers.iter().map(|s| s.table(levels)).collect()
    }
}

impl Sampler for SobolOwen {
    fn dims(&self) -> usize {
        self.sobol.dims()
    }

    fn len(&self) -> u64 {
        self.sobol.len()
    }

    fn sample(&self, index: u32, dim: usize) -> qmckit::Result<u32> {
        let x = self.sobol.sample(index, dim)?;
        let s = self
            .scramblers
            .get(dim)
            .copied()
            .unwrap_or(ExactOwen::new(0).scrambler(0));
        Ok(s.scramble(x) & self.mask())
    }

    fn fill(&self, start: u32, out: &mut [u32]) -> qmckit::Result<()> {
        self.fill_as(start, out)
    }

    fn fill_as<T: FromFraction>(&self, start: u32, out: &mut [T]) -> qmckit::Result<()> {
        let rows = qmckit::sampler::check_fill(self, start, out.len())?;
        let dims = self.dims();
        if rows == 0 || dims == 0 {
            return Ok(());
        }
        let tables = self.tables(rows);
        let mut buf = vec![0u32; BLOCK_ROWS.min(rows) * dims];
        for (b, block) in out.chunks_mut(BLOCK_ROWS * dims).enumerate() {
            let tmp = buf.get_mut(..block.len()).unwrap_or(&mut []);
            // start + b BLOCK_ROWS + (rows of the block) <= start + rows (checked).
            self.sobol.fill(start + (b * BLOCK_ROWS) as u32, tmp)?;
            for (dim, t) in tables.iter().enumerate() {
                if let Some(column) = tmp.get_mut(dim..) {
                    t.scramble_top_strided(column, dims, self.bits);
                }
            }
            for (o, &x) in block.iter_mut().zip(tmp.iter()) {
                *o = T::from_fraction(x);
            }
        }
        Ok(())
    }
}
