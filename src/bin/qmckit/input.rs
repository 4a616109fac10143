//! Reading point sets for the commands that measure them (`discrepancy`, `spectrum`).

use std::io::Read;

use qmckit::analysis::pointfile::{PointSet, parse_point_sets};

use crate::Failure;

/// Reads the input text; `name` is how errors refer to it.
fn read_input(file: Option<&str>) -> Result<(String, String), Failure> {
    let mut bytes = Vec::new();
    let name = match file {
        None | Some("-") => {
            std::io::stdin()
                .lock()
                .read_to_end(&mut bytes)
                .map_err(|e| Failure::usage(format!("<stdin>: {e}")))?;
            "<stdin>".to_owned()
        }
        Some(path) => {
            bytes = std::fs::read(path).map_err(|e| Failure::usage(format!("{path}: {e}")))?;
            path.to_owned()
        }
    };
    let text = String::from_utf8(bytes).map_err(|e| {
        Failure::usage(format!(
            "{name}: not UTF-8 text (byte {})",
            e.utf8_error().valid_up_to()
        ))
    })?;
    Ok((name, text))
}

/// The point sets of `file` (`-` or none: standard input) and the name errors give it.
pub fn read_point_sets(file: Option<&str>) -> Result<(String, Vec<PointSet>), Failure> {
    let (name, text) = read_input(file)?;
    let sets = parse_point_sets(&text).map_err(|e| Failure::usage(format!("{name}: {e}")))?;
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
