//! Point output formats: `u32`, `csv`, `npy`.

use std::io::Write;

use clap::ValueEnum;

use super::Failure;

/// How points are written.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum Format {
    /// One point a line: D decimal integers (the 0.32 numerators x * 2^32), space-separated.
    U32,
    /// One point a line: D comma-separated decimals (shortest text that parses back to the
    /// exact value x / 2^32).
    Csv,
    /// A NumPy .npy file: float64, shape (N, D), C order.
    Npy,
}

/// Writes rows of `dims` coordinates in one format; `finish` completes the stream.
pub enum PointWriter<W: Write> {
    /// Text formats.
    Text {
        out: W,
        format: Format,
        line: String,
    },
    /// NumPy.
    Npy(npyz::NpyWriter<f64, W>),
}

impl<W: Write> PointWriter<W> {
    /// A writer for `n` points of `dims` coordinates.
    pub fn new(out: W, format: Format, n: u64, dims: usize) -> Result<Self, Failure> {
        Ok(match format {
            Format::U32 | Format::Csv => PointWriter::Text {
                out,
                format,
                line: String::new(),
            },
            Format::Npy => {
                use npyz::WriterBuilder;
                let w = npyz::WriteOptions::<f64>::new()
                    .default_dtype()
                    .shape(&[n, dims as u64])
                    .writer(out)
                    .begin_nd()?;
                PointWriter::Npy(w)
            }
        })
    }

    /// Writes the points in `coords` (row-major, `dims` a point): 0.32 fractions.
    pub fn write(&mut self, coords: &[u32], dims: usize) -> Result<(), Failure> {
        self.write_rows(
            coords,
            dims,
            |line, format, x| {
                use std::fmt::Write as _;
                match format {
                    Format::Csv => write!(line, "{}", qmckit::bits::to_f64(x)),
                    _ => write!(line, "{x}"),
                }
                .expect("writing to a String cannot fail")
            },
            qmckit::bits::to_f64,
        )
    }

    /// Writes real-valued points (warped samples): shortest decimals that parse back to the
    /// same `f32`, or float64 in npy.
    pub fn write_f32(&mut self, coords: &[f32], dims: usize) -> Result<(), Failure> {
        self.write_rows(
            coords,
            dims,
            |line, _, x| {
                use std::fmt::Write as _;
                write!(line, "{x}").expect("writing to a String cannot fail")
            },
            f64::from,
        )
    }

    /// The shared row writer: `text` formats one value, `number` gives the npy value.
    fn write_rows<T: Copy>(
        &mut self,
        coords: &[T],
        dims: usize,
        text: impl Fn(&mut String, Format, T),
        number: impl Fn(T) -> f64,
    ) -> Result<(), Failure> {
        match self {
            PointWriter::Text { out, format, line } => {
                for row in coords.chunks_exact(dims.max(1)) {
                    line.clear();
                    for (k, &x) in row.iter().enumerate() {
                        if k > 0 {
                            line.push(if *format == Format::Csv { ',' } else { ' ' });
                        }
                        text(line, *format, x);
                    }
                    line.push('\n');
                    out.write_all(line.as_bytes())?;
                }
            }
            PointWriter::Npy(w) => {
                for &x in coords {
                    w.push(&number(x))?;
                }
            }
        }
        Ok(())
    }

    /// Flushes and completes the output.
    pub fn finish(self) -> Result<(), Failure> {
        match self {
            PointWriter::Text { mut out, .. } => out.flush()?,
            PointWriter::Npy(w) => w.finish()?,
        }
        Ok(())
    }
}
