//! Point output formats: `decimal` (the default), `u32`, `csv`, `npy`.

use std::io::Write;

use clap::ValueEnum;

use super::Failure;

/// How points are written.
#[derive(Clone, Copy, Debug, PartialEq, Eq, ValueEnum)]
pub enum Format {
    /// One point a line: D space-separated decimals, the shortest text that parses back to
    /// the exact value x / 2^32 (every 0.32 fraction is an f64).
    Decimal,
    /// One point a line: D decimal integers (the 0.32 numerators x * 2^32), space-separated.
    U32,
    /// One point a line: D comma-separated decimals (shortest text that parses back to the
    /// exact value x / 2^32).
    Csv,
    /// A NumPy .npy file: float64, shape (N, D), C order.
    Npy,
}

/// Bytes of text gathered before they are handed to the writer: a point of any width is
/// written in pieces of about this size, never built whole (a point of 2^27 coordinates
/// would be a 3 GB line).
const TEXT_CHUNK: usize = 1 << 16;

/// Writes rows of `dims` coordinates in one format; `finish` completes the stream.
pub enum PointWriter<W: Write> {
    /// Text formats: `text` gathers at most about [`TEXT_CHUNK`] bytes before they go out.
    Text {
        out: W,
        format: Format,
        text: String,
    },
    /// NumPy.
    Npy(npyz::NpyWriter<f64, W>),
}

impl<W: Write> PointWriter<W> {
    /// A writer for `n` points of `dims` coordinates.
    pub fn new(out: W, format: Format, n: u64, dims: usize) -> Result<Self, Failure> {
        Ok(match format {
            Format::Decimal | Format::U32 | Format::Csv => PointWriter::Text {
                out,
                format,
                text: String::new(),
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
                    Format::U32 => write!(line, "{x}"),
                    _ => write!(line, "{}", qmckit::bits::to_f64(x)),
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

    /// The shared row writer: `value` formats one value, `number` gives the npy value.
    /// Text is streamed: it goes out whenever [`TEXT_CHUNK`] bytes have gathered, within a
    /// row as between rows, so memory stays bounded for any row width.
    fn write_rows<T: Copy>(
        &mut self,
        coords: &[T],
        dims: usize,
        value: impl Fn(&mut String, Format, T),
        number: impl Fn(T) -> f64,
    ) -> Result<(), Failure> {
        match self {
            PointWriter::Text { out, format, text } => {
                let separator = if *format == Format::Csv { ',' } else { ' ' };
                for row in coords.chunks_exact(dims.max(1)) {
                    for (k, &x) in row.iter().enumerate() {
                        if k > 0 {
                            text.push(separator);
                        }
                        value(text, *format, x);
                        if text.len() >= TEXT_CHUNK {
                            out.write_all(text.as_bytes())?;
                            text.clear();
                        }
                    }
                    text.push('\n');
                }
                out.write_all(text.as_bytes())?;
                text.clear();
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

#[cfg(test)]
mod tests {
    use super::{Format, PointWriter, TEXT_CHUNK};

    /// A sink that keeps the largest single write and the bytes in all.
    #[derive(Default)]
    struct Sink {
        largest: usize,
        bytes: Vec<u8>,
    }

    impl std::io::Write for Sink {
        fn write(&mut self, buf: &[u8]) -> std::io::Result<usize> {
            self.largest = self.largest.max(buf.len());
            self.bytes.extend_from_slice(buf);
            Ok(buf.len())
        }

        fn flush(&mut self) -> std::io::Result<()> {
            Ok(())
        }
    }

    #[test]
    fn a_wide_point_is_written_in_pieces() {
        // One point of 2^18 coordinates: about 5 MB of csv, never held whole.
        let dims = 1 << 18;
        let coords: Vec<u32> = (0..dims as u32)
            .map(|i| i.wrapping_mul(2_654_435_761))
            .collect();
        for format in [Format::Csv, Format::Decimal, Format::U32] {
            let mut w = PointWriter::new(Sink::default(), format, 1, dims).unwrap();
            w.write(&coords, dims).unwrap();
            w.write(&coords[..3], 3).unwrap();
            let PointWriter::Text { out, .. } = w else {
                panic!("a text writer")
            };
            assert!(out.largest <= TEXT_CHUNK + 32, "{}", out.largest);
            let text = String::from_utf8(out.bytes).unwrap();
            let lines: Vec<&str> = text.lines().collect();
            assert_eq!(lines.len(), 2);
            let sep = if format == Format::Csv { ',' } else { ' ' };
            let values: Vec<&str> = lines[0].split(sep).collect();
            assert_eq!(values.len(), dims);
            for (v, &x) in values.iter().zip(&coords) {
                match format {
                    Format::U32 => assert_eq!(v.parse::<u32>().unwrap(), x),
                    _ => assert_eq!(v.parse::<f64>().unwrap(), f64::from(x) / 4294967296.0),
                }
            }
            assert_eq!(lines[1].split(sep).count(), 3);
        }
    }
}
