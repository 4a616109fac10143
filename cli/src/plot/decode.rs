//! Reading images and measurement tables for figures: PGM (P2/P5, 8 or 16 bits), PNG
//! (grey or colour, 8 or 16 bits; colour read as Rec. 709 luminance), whitespace-separated
//! text rows (e.g. `qmckit mask`'s rank masks), and the text tables `qmckit spectrum` and
//! `qmckit convergence` write.

use super::backend::PlotError;

/// The largest image read (pixels).
const MAX_PIXELS: usize = 1 << 22;

/// The most rows a measurement table holds (a figure draws at most this many elements).
const MAX_ROWS: usize = super::backend::MAX_ELEMENTS;

/// The most numbers on one line of a measurement table (its rows hold a few columns).
const MAX_COLUMNS: usize = 1024;

/// A decoded image: `(width, height, values)`, row-major from the top, values as stored
/// (grey levels, or ranks for a text mask).
pub type Decoded = (usize, usize, Vec<f64>);

fn err(m: impl Into<String>) -> PlotError {
    PlotError::new(m)
}

fn check_size(w: usize, h: usize) -> Result<(), PlotError> {
    if w == 0 || h == 0 || w.saturating_mul(h) > MAX_PIXELS {
        return Err(err(format!(
            "image size {w}x{h} is outside 1 to {MAX_PIXELS} pixels"
        )));
    }
    Ok(())
}

/// Decodes a PGM, PNG or text image, told apart by their first bytes (`P2`/`P5`, the PNG
/// signature, else text).
///
/// # Errors
/// A [`PlotError`] naming what is wrong: truncated data, a bad header, ragged text rows,
/// more than 2^22 pixels.
pub fn decode_image(bytes: &[u8]) -> Result<Decoded, PlotError> {
    if bytes.starts_with(b"\x89PNG") {
        decode_png(bytes)
    } else if bytes.starts_with(b"P5") || bytes.starts_with(b"P2") {
        decode_pgm(bytes)
    } else {
        let text = std::str::from_utf8(bytes)
            .map_err(|_| err("an image must be PGM, PNG or text rows of numbers"))?;
        decode_text(text)
    }
}

fn decode_png(bytes: &[u8]) -> Result<Decoded, PlotError> {
    let mut decoder = png::Decoder::new(std::io::Cursor::new(bytes));
    decoder.set_transformations(png::Transformations::EXPAND);
    let mut reader = decoder.read_info().map_err(|e| err(format!("PNG: {e}")))?;
    let (w, h) = {
        let info = reader.info();
        (info.width as usize, info.height as usize)
    };
    check_size(w, h)?;
    let size = reader
        .output_buffer_size()
        .ok_or_else(|| err("PNG: the image is too large"))?;
    let mut buf: Vec<u8> = qmckit::size::vec_zeroed(size).map_err(|e| err(format!("PNG: {e}")))?;
    let frame = reader
        .next_frame(&mut buf)
        .map_err(|e| err(format!("PNG: {e}")))?;
    let channels = frame.color_type.samples();
    let wide = frame.bit_depth == png::BitDepth::Sixteen;
    let bytes_per = if wide { 2 } else { 1 };
    let truncated = || err("PNG: the decoded frame is shorter than its size");
    let sample = |i: usize| -> Result<f64, PlotError> {
        let v = if wide {
            let at = i.checked_mul(2).ok_or_else(truncated)?;
            match buf.get(at..at + 2) {
                Some(&[a, b]) => u16::from_be_bytes([a, b]) as f64,
                _ => return Err(truncated()),
            }
        } else {
            *buf.get(i).ok_or_else(truncated)? as f64
        };
        Ok(v)
    };
    let line = frame.line_size;
    let mut out: Vec<f64> =
        qmckit::size::vec_with_capacity(w * h).map_err(|e| err(format!("PNG: {e}")))?;
    for y in 0..h {
        for x in 0..w {
            // w, h <= 2^22 and line <= 8 w bytes: no overflow.
            let base = (y * line) / bytes_per + x * channels;
            let v = if channels >= 3 {
                0.2126 * sample(base)? + 0.7152 * sample(base + 1)? + 0.0722 * sample(base + 2)?
            } else {
                sample(base)?
            };
            out.push(v);
        }
    }
    Ok((w, h, out))
}

/// The next whitespace-separated header token of a PGM (comments skipped) and the rest.
fn token(mut s: &[u8]) -> Option<(&[u8], &[u8])> {
    loop {
        while let [c, rest @ ..] = s {
            if c.is_ascii_whitespace() {
                s = rest;
            } else {
                break;
            }
        }
        if s.first() == Some(&b'#') {
            let end = s.iter().position(|&c| c == b'\n').unwrap_or(s.len());
            s = &s[end..];
            continue;
        }
        let end = s
            .iter()
            .position(|c| c.is_ascii_whitespace())
            .unwrap_or(s.len());
        return (end > 0).then_some((&s[..end], &s[end..]));
    }
}

fn number<'a>(t: Option<(&'a [u8], &'a [u8])>, what: &str) -> Result<(usize, &'a [u8]), PlotError> {
    let (tok, rest) = t.ok_or_else(|| err(format!("PGM: the header ends before its {what}")))?;
    let v = std::str::from_utf8(tok)
        .ok()
        .and_then(|s| s.parse::<usize>().ok())
        .ok_or_else(|| err(format!("PGM: bad {what}")))?;
    Ok((v, rest))
}

fn decode_pgm(bytes: &[u8]) -> Result<Decoded, PlotError> {
    let binary = bytes.starts_with(b"P5");
    let rest = &bytes[2..];
    let (w, rest) = number(token(rest), "width")?;
    let (h, rest) = number(token(rest), "height")?;
    let (maxval, rest) = number(token(rest), "maxval")?;
    check_size(w, h)?;
    if maxval == 0 || maxval > 65535 {
        return Err(err("PGM: maxval must be in 1..=65535"));
    }
    let n = w * h;
    if binary {
        let data = rest.get(1..).unwrap_or(&[]);
        let wide = maxval > 255;
        let need = if wide { 2 * n } else { n };
        if data.len() < need {
            return Err(err(format!(
                "PGM: {} bytes of pixels, {need} needed",
                data.len()
            )));
        }
        let v = (0..n)
            .map(|i| {
                if wide {
                    u16::from_be_bytes([data[2 * i], data[2 * i + 1]]) as f64
                } else {
                    data[i] as f64
                }
            })
            .collect();
        Ok((w, h, v))
    } else {
        let text = std::str::from_utf8(rest).map_err(|_| err("PGM: P2 pixels must be text"))?;
        let v: Vec<f64> = text
            .split_ascii_whitespace()
            .take(n)
            .map(|t| t.parse::<u32>().map(f64::from))
            .collect::<Result<_, _>>()
            .map_err(|_| err("PGM: a P2 pixel is not a whole number"))?;
        if v.len() < n {
            return Err(err(format!("PGM: {} pixels, {n} needed", v.len())));
        }
        Ok((w, h, v))
    }
}

fn decode_text(text: &str) -> Result<Decoded, PlotError> {
    let mut w = 0;
    let mut v = Vec::new();
    let mut rows = 0;
    for (k, line) in text.lines().enumerate() {
        let line = line.split('#').next().unwrap_or("").trim();
        if line.is_empty() {
            continue;
        }
        let start = v.len();
        for word in line
            .split(|c: char| c == ',' || c.is_ascii_whitespace())
            .filter(|s| !s.is_empty())
        {
            let x = word
                .parse::<f64>()
                .ok()
                .filter(|x| x.is_finite())
                .ok_or_else(|| err(format!("line {}: not a row of finite numbers", k + 1)))?;
            // Checked before growing: the image never holds more than MAX_PIXELS values.
            if v.len() >= MAX_PIXELS {
                return Err(err(format!("more than {MAX_PIXELS} pixels")));
            }
            v.push(x);
        }
        let len = v.len() - start;
        if rows == 0 {
            w = len;
        } else if len != w {
            return Err(err(format!(
                "line {}: {len} values, the first row has {w}",
                k + 1
            )));
        }
        rows += 1;
    }
    check_size(w, rows).map_err(|_| err("the input holds no image (no rows of numbers)"))?;
    Ok((w, rows, v))
}

/// One block of a measurement table: its rows, and the name a `# label: NAME` line gave it.
#[derive(Clone, Debug, PartialEq)]
pub struct Block {
    /// The block's name, if a `# label:` line gave one.
    pub label: Option<String>,
    /// Rows of numbers.
    pub rows: Vec<Vec<f64>>,
}

/// Rows of numbers from a measurement table: lines not starting with `#`, split on
/// whitespace, each with at least `min_columns` and at most 1024 finite numbers,
/// at most 2^22 rows in all (the most a figure draws). Blocks separated by
/// `# set K` or `# mean ...` lines (`qmckit spectrum` with several sets) or by lines holding
/// only `#` are kept apart: the result has one entry per block. A `# label: NAME` line names
/// the block it is in.
///
/// # Errors
/// A [`PlotError`] for a line that is not numbers, a short or long line, too many rows, or
/// no rows at all.
pub fn parse_blocks(text: &str, min_columns: usize) -> Result<Vec<Block>, PlotError> {
    let empty = || Block {
        label: None,
        rows: Vec::new(),
    };
    let mut blocks = vec![empty()];
    let mut total = 0usize;
    for (k, line) in text.lines().enumerate() {
        let line = line.trim();
        if line == "#" || line.starts_with("# set") || line.starts_with("# mean") {
            if !blocks.last().is_some_and(|b| b.rows.is_empty()) {
                blocks.push(empty());
            }
            continue;
        }
        if let Some(name) = line.strip_prefix("# label:") {
            if let Some(b) = blocks.last_mut() {
                b.label = Some(name.trim().to_owned());
            }
            continue;
        }
        if line.is_empty() || line.starts_with('#') {
            continue;
        }
        let row: Vec<f64> = line
            .split_ascii_whitespace()
            .take(MAX_COLUMNS + 1)
            .map(|s| s.parse::<f64>().ok().filter(|x| x.is_finite()))
            .collect::<Option<_>>()
            .ok_or_else(|| err(format!("line {}: not a row of numbers", k + 1)))?;
        if row.len() > MAX_COLUMNS {
            return Err(err(format!(
                "line {}: more than {MAX_COLUMNS} values",
                k + 1
            )));
        }
        total += 1;
        if total > MAX_ROWS {
            return Err(err(format!(
                "line {}: more than {MAX_ROWS} rows of numbers",
                k + 1
            )));
        }
        if row.len() < min_columns {
            return Err(err(format!(
                "line {}: {} values, at least {min_columns} expected",
                k + 1,
                row.len()
            )));
        }
        if let Some(b) = blocks.last_mut() {
            b.rows.push(row);
        }
    }
    blocks.retain(|b| !b.rows.is_empty());
    if blocks.is_empty() {
        return Err(err("the input holds no rows of numbers"));
    }
    Ok(blocks)
}

/// The rows of [`parse_blocks`], without the labels.
///
/// # Errors
/// As [`parse_blocks`].
pub fn parse_table(text: &str, min_columns: usize) -> Result<Vec<Vec<Vec<f64>>>, PlotError> {
    Ok(parse_blocks(text, min_columns)?
        .into_iter()
        .map(|b| b.rows)
        .collect())
}
