//! Reading point sets for the commands that measure them (`discrepancy`, `spectrum`): text in
//! the point-file format (real numbers or qmckit's `u32` numerators) or NumPy `.npy` files,
//! so that whatever `qmckit points` writes reads back with default options.

use std::io::Read;

use clap::{Args, ValueEnum};
use qmckit::analysis::pointfile::{Encoding, PointSet, parse_point_sets_as};

use super::Failure;

/// How text input writes its coordinates (`--input-format`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, ValueEnum)]
pub enum InputFormat {
    /// u32 when every value is a whole number and one exceeds 1 (`points --format u32`),
    /// else real numbers; .npy files are recognized by their magic bytes.
    #[default]
    Auto,
    /// Real numbers in [0, 1].
    Real,
    /// 0.32 numerators: integers in 0..=4294967295, read as x / 2^32.
    U32,
}

/// The input options shared by the measuring commands.
#[derive(Args, Debug, Clone)]
pub struct InputArgs {
    /// How text coordinates are written (npy files are always recognized).
    #[arg(long, value_enum, default_value_t = InputFormat::Auto, value_name = "FORMAT")]
    pub input_format: InputFormat,
    /// Point file (text or .npy); '-' or none reads standard input.
    pub file: Option<String>,
}

/// The first bytes of every NumPy `.npy` file.
const NPY_MAGIC: &[u8] = b"\x93NUMPY";

/// The first bytes of every PNG file.
const PNG_MAGIC: &[u8] = b"\x89PNG";

/// The binary formats read (by their first bytes): NumPy, PNG and binary PGM. Everything
/// else is text: UTF-8, in lines.
const BINARY: [&[u8]; 3] = [NPY_MAGIC, PNG_MAGIC, b"P5"];

/// The running checks of a text input, fed each chunk as it arrives: UTF-8 (so random bytes
/// are refused within the first chunk, not after a gigabyte), the length of each line, and
/// the number of lines that hold something before a `#` (a lower bound on the records).
#[derive(Default)]
struct TextScan {
    /// Bytes of the input already checked.
    scanned: usize,
    /// Bytes of the input known to be valid UTF-8.
    valid: usize,
    line_len: usize,
    line_no: u64,
    records: u64,
    has_content: bool,
    in_comment: bool,
}

impl TextScan {
    /// Checks the bytes of `all` past those already seen.
    fn feed(&mut self, all: &[u8], limits: Limits) -> Result<(), String> {
        let fresh = all.get(self.scanned..).unwrap_or(&[]);
        for &b in fresh {
            match b {
                b'\n' | b'\r' => {
                    self.line_no += u64::from(b == b'\n');
                    self.end_line(limits)?;
                }
                _ => {
                    self.line_len += 1;
                    if self.line_len > limits.line {
                        return Err(format!(
                            "line {} is longer than {} bytes (not a text of points?)",
                            self.line_no + 1,
                            limits.line
                        ));
                    }
                    if b == b'#' {
                        self.in_comment = true;
                    } else if !self.in_comment && !matches!(b, b' ' | b'\t' | b',') {
                        self.has_content = true;
                    }
                }
            }
        }
        self.scanned = all.len();
        match std::str::from_utf8(&all[self.valid..]) {
            Ok(_) => self.valid = all.len(),
            Err(e) => match e.error_len() {
                // A character cut by the chunk's end: checked with the next chunk.
                None => self.valid += e.valid_up_to(),
                Some(_) => {
                    return Err(format!(
                        "not UTF-8 text (byte {}) nor a file format read here",
                        self.valid + e.valid_up_to()
                    ));
                }
            },
        }
        Ok(())
    }

    /// Counts the line that ends here.
    fn end_line(&mut self, limits: Limits) -> Result<(), String> {
        self.records += u64::from(self.has_content);
        if self.records > limits.records {
            return Err(format!(
                "more than {} records (lines of data); split the input",
                limits.records
            ));
        }
        self.line_len = 0;
        self.has_content = false;
        self.in_comment = false;
        Ok(())
    }

    /// The checks at the end of the input (its last line, a cut character).
    fn finish(&mut self, all: &[u8], limits: Limits) -> Result<(), String> {
        if self.has_content {
            self.end_line(limits)?;
        }
        if self.valid < all.len() {
            return Err(format!(
                "not UTF-8 text (byte {}) nor a file format read here",
                self.valid
            ));
        }
        Ok(())
    }
}

/// The bounds of one input: the bytes read and the longest line of a text.
#[derive(Clone, Copy, Debug)]
pub struct Limits {
    /// The most bytes read; a regular file longer than this is refused before reading.
    pub bytes: u64,
    /// The longest line of a text input, in bytes (binary formats, recognized by their
    /// magic bytes, have no lines).
    pub line: usize,
    /// The option that names the input (`--vector`), or empty for the main input.
    pub option: &'static str,
    /// The most lines holding data (anything before a `#`) a text may have: a lower bound
    /// on what its parser would build, so an input too large to parse is refused as it is
    /// read.
    pub records: u64,
}

/// The limits of a point file, table or image: the crate's allocation limit (1 GiB), and
/// lines of at most 64 MiB (a point of 21201 coordinates written in full takes 0.5 MiB).
pub const DATA: Limits = Limits {
    bytes: qmckit::size::MAX_ALLOC_BYTES,
    line: 64 << 20,
    option: "",
    records: u64::MAX,
};

/// The limits of a point file: those of [`DATA`], and at most as many lines of data as the
/// parser admits coordinates in all (each point has at least one).
pub const POINTS: Limits = Limits {
    records: qmckit::analysis::pointfile::MAX_VALUES as u64,
    ..DATA
};

/// How much is read at a time.
const CHUNK: usize = 1 << 20;

/// The name errors give `file` (`-` or none: standard input), quoted when it holds a
/// control character so the error stays on one line.
pub fn shown_name(file: Option<&str>) -> String {
    match file {
        None | Some("-") => "<stdin>".to_owned(),
        Some(path) if path.chars().any(char::is_control) => format!("{path:?}"),
        Some(path) => path.to_owned(),
    }
}

/// The one bounded input path: reads `file` (`-` or none: standard input) within `limits`
/// and returns the name errors give it and its bytes.
///
/// Every source goes through here, files, pipes and devices alike: the bytes are counted as
/// they are actually read (a device's size is not trusted), a regular file past the limit is
/// refused from its size before anything is read, a text line past the line limit is
/// refused as soon as it passes it (so `/dev/zero` is refused within the first chunks), and
/// the buffer grows through the checked allocation helper. Cost: one pass over the input.
///
/// # Errors
/// A usage failure (exit 2) naming the input: it cannot be opened or read, or it passes a
/// limit.
pub fn read_bounded(file: Option<&str>, limits: Limits) -> Result<(String, Vec<u8>), Failure> {
    let name = shown_name(file);
    let label = if limits.option.is_empty() {
        name.clone()
    } else {
        format!("{} {name}", limits.option)
    };
    let fail = |message: String| Failure::usage(format!("{label}: {message}"));
    let mut source: Box<dyn Read> = match file {
        None | Some("-") => Box::new(std::io::stdin().lock()),
        Some(path) => {
            let f = std::fs::File::open(path).map_err(|e| fail(e.to_string()))?;
            let meta = f.metadata().map_err(|e| fail(e.to_string()))?;
            if meta.is_dir() {
                return Err(fail("is a directory".to_owned()));
            }
            if meta.is_file() && meta.len() > limits.bytes {
                return Err(fail(format!(
                    "{} bytes, more than the {} bytes read; split it into smaller files",
                    meta.len(),
                    limits.bytes
                )));
            }
            Box::new(f)
        }
    };
    let mut bytes: Vec<u8> = Vec::new();
    let mut binary = None;
    let mut scan = TextScan::default();
    let mut chunk = vec![0u8; CHUNK];
    loop {
        let got = match source.read(&mut chunk) {
            Ok(0) => break,
            Ok(k) => k,
            Err(e) if e.kind() == std::io::ErrorKind::Interrupted => continue,
            Err(e) => return Err(fail(e.to_string())),
        };
        if bytes.len() as u64 + got as u64 > limits.bytes {
            return Err(fail(format!(
                "more than {} bytes of input; split it into smaller files",
                limits.bytes
            )));
        }
        qmckit::size::reserve(&mut bytes, got).map_err(|e| fail(e.to_string()))?;
        bytes.extend_from_slice(&chunk[..got]);
        if bytes.len() < 8 && binary.is_none() {
            // Too short to tell yet; the text is checked once it is known.
            continue;
        }
        let is_binary = *binary.get_or_insert_with(|| BINARY.iter().any(|m| bytes.starts_with(m)));
        if !is_binary {
            scan.feed(&bytes, limits).map_err(fail)?;
        }
    }
    if binary != Some(true) {
        scan.feed(&bytes, limits).map_err(fail)?;
        scan.finish(&bytes, limits).map_err(fail)?;
    }
    Ok((name, bytes))
}

/// Checks the header of a `.npy` file before any parser sizes a buffer from it: the
/// header's stated length must fit in the bytes present. (The format: magic, version
/// `major.minor`, then the header length as u16 (version 1) or u32 (versions 2 and 3).)
fn check_npy_header(bytes: &[u8]) -> Result<(), String> {
    let short = || "a .npy file cut short in its preamble".to_owned();
    let major = *bytes.get(6).ok_or_else(short)?;
    let (len, start) = match major {
        1 => {
            let b = bytes.get(8..10).ok_or_else(short)?;
            (u64::from(u16::from_le_bytes([b[0], b[1]])), 10u64)
        }
        2 | 3 => {
            let b = bytes.get(8..12).ok_or_else(short)?;
            (
                u64::from(u32::from_le_bytes([b[0], b[1], b[2], b[3]])),
                12u64,
            )
        }
        v => return Err(format!("a .npy file of unknown version {v}")),
    };
    if start + len > bytes.len() as u64 {
        return Err(format!(
            "a .npy header of {len} bytes, but the file holds {} (truncated?)",
            bytes.len()
        ));
    }
    // The shape's product is checked here, before the npy parser multiplies it unchecked.
    let header = bytes
        .get(start as usize..(start + len) as usize)
        .and_then(|h| std::str::from_utf8(h).ok())
        .ok_or("a .npy header that is not text")?;
    // Only the plain dictionary of a float array is read: one '{', one '(' and no '['
    // (a structured dtype). Anything else is refused here, before the npy parser, whose
    // literal parser takes exponential time on deeply nested brackets.
    let occurrences = |c: char| header.matches(c).count();
    if header.contains('[')
        || occurrences('{') != 1
        || occurrences('(') != 1
        || occurrences(')') != 1
    {
        return Err(
            "a .npy header that is not a plain float array's (needs float64 or \
                    float32, shape (N, D) or (N,))"
                .to_owned(),
        );
    }
    let shape = header
        .split_once("'shape'")
        .and_then(|(_, rest)| rest.split_once('('))
        .and_then(|(_, rest)| rest.split_once(')'))
        .map(|(inside, _)| inside)
        .ok_or("a .npy header without a 'shape' tuple")?;
    let mut count: u64 = 1;
    for dim in shape.split(',').map(str::trim).filter(|t| !t.is_empty()) {
        let dim: u64 = dim
            .trim_end_matches('L')
            .parse()
            .map_err(|_| format!("a .npy shape ({shape}) that is not whole numbers"))?;
        count = count
            .checked_mul(dim)
            .filter(|&c| c <= bytes.len() as u64)
            .ok_or_else(|| format!("a .npy shape ({shape}) larger than the file's data"))?;
    }
    Ok(())
}

/// The point set of a `.npy` file: float64 or float32, shape (N, D) or (N,), C or Fortran
/// order.
pub fn read_npy(bytes: &[u8]) -> Result<PointSet, String> {
    check_npy_header(bytes)?;
    let file = npyz::NpyFile::new(bytes).map_err(|e| format!("not a readable .npy file: {e}"))?;
    let shape = file.shape().to_vec();
    let (n, dims) = match shape[..] {
        [n] => (n, 1),
        [n, d] => (n, d),
        _ => {
            return Err(format!(
                "a .npy array of shape {shape:?}: points need (N, D)"
            ));
        }
    };
    if n == 0 || dims == 0 {
        return Err(format!("a .npy array of shape {shape:?} holds no points"));
    }
    let fortran = file.order() == npyz::Order::Fortran;
    let item = match file.dtype() {
        npyz::DType::Plain(t) => t.size_field(),
        other => {
            return Err(format!(
                "a .npy array of dtype {other:?}: needs float64 or float32"
            ));
        }
    };
    // The header's count must be backed by data before anything is allocated for it.
    let len = qmckit::size::coordinates(n, dims as usize).map_err(|e| e.to_string())?;
    // The parsed form (f64) is held twice at most (Fortran order is transposed).
    qmckit::size::bytes(len, 2 * std::mem::size_of::<f64>()).map_err(|e| e.to_string())?;
    if (len as u64).saturating_mul(item as u64) > bytes.len() as u64 {
        return Err(format!(
            "a .npy header for {n} x {dims} values, but the file holds fewer (truncated?)"
        ));
    }
    let data: Vec<f64> = match file.try_data::<f64>() {
        Ok(r) => r.collect::<Result<_, _>>(),
        Err(file) => match file.try_data::<f32>() {
            Ok(r) => r.map(|x| x.map(f64::from)).collect::<Result<_, _>>(),
            Err(file) => {
                return Err(format!(
                    "a .npy array of dtype {}: needs float64 or float32",
                    file.dtype().descr()
                ));
            }
        },
    }
    .map_err(|e| format!("reading the .npy data: {e}"))?;
    let dims = dims as usize;
    let data = if fortran && dims > 1 {
        let n = n as usize;
        (0..len).map(|k| data[(k % dims) * n + k / dims]).collect()
    } else {
        data
    };
    if let Some(k) = data.iter().position(|x| !(0.0..=1.0).contains(x)) {
        return Err(format!(
            "point {}, coordinate {}: {} is not in [0, 1] (0-based)",
            k / dims,
            k % dims,
            data[k]
        ));
    }
    Ok(PointSet { dims, data })
}

/// The point sets of the input (`-` or none: standard input) and the name errors give it.
pub fn read_point_sets(input: &InputArgs) -> Result<(String, Vec<PointSet>), Failure> {
    let (name, bytes) = read_bounded(input.file.as_deref(), POINTS)?;
    if bytes.starts_with(NPY_MAGIC) {
        let set = read_npy(&bytes).map_err(|e| Failure::usage(format!("{name}: {e}")))?;
        return Ok((name, vec![set]));
    }
    let text = String::from_utf8(bytes).map_err(|e| {
        Failure::usage(format!(
            "{name}: not UTF-8 text (byte {}) nor a .npy file",
            e.utf8_error().valid_up_to()
        ))
    })?;
    let encoding = match input.input_format {
        InputFormat::Auto => Encoding::Auto,
        InputFormat::Real => Encoding::Real,
        InputFormat::U32 => Encoding::U32,
    };
    let sets =
        parse_point_sets_as(&text, encoding).map_err(|e| Failure::usage(format!("{name}: {e}")))?;
    Ok((name, sets))
}

/// How errors name set `k` (0-based) of `count`: `set K: `, or nothing for a single set.
pub fn set_label(k: usize, count: usize) -> String {
    if count > 1 {
        format!("set {}: ", k + 1)
    } else {
        String::new()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scratch(name: &str, bytes: &[u8]) -> String {
        let p = std::env::temp_dir().join(format!("qmckit-input-{name}-{}", std::process::id()));
        std::fs::write(&p, bytes).unwrap();
        p.to_string_lossy().into_owned()
    }

    #[test]
    fn limits_are_counted_on_the_bytes_read() {
        let small = Limits {
            bytes: 16,
            line: 4,
            option: "--vector",
            records: 3,
        };
        let ok = scratch("ok", b"0.5\n0.25\r\n1\n");
        assert_eq!(read_bounded(Some(&ok), small).unwrap().1.len(), 12);
        // Past the byte limit: refused from the size, before reading.
        let big = scratch("big", &[b'1'; 17]);
        let e = read_bounded(Some(&big), small).unwrap_err();
        assert!(e.message.starts_with("--vector ") && e.message.contains("17 bytes"));
        // A long line: refused at the line, whatever the byte limit.
        let long = scratch("long", b"0.5\n0.125\n");
        let e = read_bounded(Some(&long), small).unwrap_err();
        assert!(
            e.message.contains("line 2 is longer than 4 bytes"),
            "{}",
            e.message
        );
        // A device: its size says nothing; the bytes read are counted.
        let e = read_bounded(Some("/dev/zero"), DATA).unwrap_err();
        assert!(e.message.contains("line 1 is longer than"), "{}", e.message);
        // Bytes that are not UTF-8: refused as read.
        let e = read_bounded(Some("/dev/urandom"), DATA).unwrap_err();
        assert!(e.message.contains("not UTF-8"), "{}", e.message);
        // More lines of data than the records allowed (comments and blanks do not count).
        let many = scratch("many", b"1\n# c\n\n2\n3\n4\n");
        let e = read_bounded(Some(&many), Limits { bytes: 64, ..small }).unwrap_err();
        assert!(e.message.contains("more than 3 records"), "{}", e.message);
        let three = scratch("three", b"1\n# c\n\n2\n3");
        assert!(read_bounded(Some(&three), Limits { bytes: 64, ..small }).is_ok());
        for f in [ok, big, long, many, three] {
            std::fs::remove_file(f).unwrap();
        }
    }

    #[test]
    fn npy_headers_are_bounded_before_parsing() {
        let mut evil = b"\x93NUMPY\x02\x00".to_vec();
        evil.extend_from_slice(&u32::MAX.to_le_bytes());
        evil.extend_from_slice(b"{}      ");
        assert!(check_npy_header(&evil).unwrap_err().contains("4294967295"));
        assert!(read_npy(&evil).is_err());
        assert!(check_npy_header(b"\x93NUMPY\x01").is_err());
        assert!(check_npy_header(b"\x93NUMPY\x07\x00\x00\x00").is_err());
        let npy = |dict: &str| {
            let mut v = b"\x93NUMPY\x01\x00".to_vec();
            v.extend_from_slice(&(dict.len() as u16).to_le_bytes());
            v.extend_from_slice(dict.as_bytes());
            v.extend_from_slice(&[0u8; 64]);
            v
        };
        assert!(check_npy_header(&npy("{'descr': '<f8', 'shape': (2, 3), }")).is_ok());
        let huge = "{'descr': '<f8', 'shape': (4294967296, 4294967296), }";
        assert!(check_npy_header(&npy(huge)).unwrap_err().contains("larger"));
        assert!(check_npy_header(&npy("{'descr': '<f8', }")).is_err());
        let nested = format!("{{'descr': '<f8', {}'shape': (4, 2), }}", "[".repeat(60));
        assert!(check_npy_header(&npy(&nested)).is_err());
    }
}
