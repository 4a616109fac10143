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

/// The largest input read: the crate's allocation limit (an endless input such as
/// `/dev/zero` is refused once it passes it).
const MAX_INPUT_BYTES: u64 = qmckit::size::MAX_ALLOC_BYTES;

/// Reads the input bytes (at most [`MAX_INPUT_BYTES`]); the name errors give them.
fn read_input(file: Option<&str>) -> Result<(String, Vec<u8>), Failure> {
    let mut bytes = Vec::new();
    let (name, result) = match file {
        None | Some("-") => (
            "<stdin>".to_owned(),
            std::io::stdin()
                .lock()
                .take(MAX_INPUT_BYTES + 1)
                .read_to_end(&mut bytes),
        ),
        Some(path) => (
            // A name with a line break or other control character is quoted, so the
            // error stays on one line.
            if path.chars().any(char::is_control) {
                format!("{path:?}")
            } else {
                path.to_owned()
            },
            std::fs::File::open(path)
                .and_then(|f| f.take(MAX_INPUT_BYTES + 1).read_to_end(&mut bytes)),
        ),
    };
    result.map_err(|e| Failure::usage(format!("{name}: {e}")))?;
    if bytes.len() as u64 > MAX_INPUT_BYTES {
        return Err(Failure::usage(format!(
            "{name}: more than {MAX_INPUT_BYTES} bytes of input; split it into smaller files"
        )));
    }
    Ok((name, bytes))
}

/// The point set of a `.npy` file: float64 or float32, shape (N, D) or (N,), C or Fortran
/// order.
fn read_npy(bytes: &[u8]) -> Result<PointSet, String> {
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
    let (name, bytes) = read_input(input.file.as_deref())?;
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
