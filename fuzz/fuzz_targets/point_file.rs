//! Fuzzes the point-file parser behind `qmckit discrepancy` and `qmckit spectrum`: any byte
//! string must give either point sets that satisfy the parser's promises or an error that
//! names a line, and never a panic.
#![no_main]

use libfuzzer_sys::fuzz_target;
use qmckit::analysis::Points;
use qmckit::analysis::pointfile::parse_point_sets;

fuzz_target!(|data: &[u8]| {
    let Ok(text) = std::str::from_utf8(data) else {
        return;
    };
    match parse_point_sets(text) {
        Ok(sets) => {
            assert!(!sets.is_empty());
            for set in &sets {
                // Every set the parser accepts is a valid `Points` view.
                assert!(Points::new(&set.data, set.dims).is_ok());
            }
        }
        Err(e) => {
            assert!(e.line >= 1);
            assert!(!e.to_string().contains('\n'));
        }
    }
});
