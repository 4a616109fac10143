//! Sentences about measured numbers, computed from the numbers they describe: each states
//! what the numbers shown beside it say (counts, orders, fitted slopes with their values)
//! and says something else when they do.

use super::sig;

/// `|a - b|` in units of `se`: infinite when `se` is zero (or not finite) and `a != b`.
pub fn z_score(a: f64, b: f64, se: f64) -> f64 {
    let d = (a - b).abs();
    if d == 0.0 {
        0.0
    } else if se > 0.0 && se.is_finite() {
        d / se
    } else {
        f64::INFINITY
    }
}

/// `n of m` when some hold, `all m` when all do, `none of the m` when none does.
fn n_of_m(n: usize, m: usize) -> String {
    match n {
        0 => format!("none of the {m}"),
        n if n == m => format!("all {m}"),
        n => format!("{n} of {m}"),
    }
}

/// Names joined as `a, b and c`.
fn joined(names: &[String]) -> String {
    match names {
        [] => String::new(),
        [one] => one.clone(),
        [rest @ .., last] => format!("{} and {last}", rest.join(", ")),
    }
}

/// Predictions against measurements with standard errors, `(name, predicted, measured,
/// std_error)` a row: how many agree within `k` standard errors, with every row's distance.
pub fn agreement(rows: &[(&str, f64, f64, f64)], k: f64) -> String {
    let z: Vec<(String, f64)> = rows
        .iter()
        .map(|&(name, p, m, se)| (name.to_owned(), z_score(p, m, se)))
        .collect();
    // A NaN distance (a measurement that is not a number) is not within.
    let agrees = |z: f64| z <= k;
    let within = z.iter().filter(|(_, z)| agrees(*z)).count();
    let list: Vec<String> = z
        .iter()
        .map(|(name, z)| format!("{name} {}", sig(*z, 3)))
        .collect();
    let outside: Vec<String> = z
        .iter()
        .filter(|(_, z)| !agrees(*z))
        .map(|(name, _)| name.clone())
        .collect();
    let mut s = format!(
        "Prediction and measurement agree within {k} standard errors in {} rows \
         (|predicted - measured| / standard error: {})",
        n_of_m(within, rows.len()),
        list.join(", ")
    );
    if !outside.is_empty() {
        s.push_str(&format!(
            "; they differ by more than {k} standard errors for {}",
            joined(&outside)
        ));
    }
    s.push('.');
    s
}

/// Whether `values`, listed in the order expected from the largest down, are strictly in
/// that order.
pub fn in_order(values: &[(&str, f64)]) -> bool {
    values.windows(2).all(|w| w[0].1 > w[1].1)
}

/// `values` (name, value), listed in the expected order from the largest down: the measured
/// order with the values, and whether it is the expected one.
pub fn order(what: &str, values: &[(&str, f64)]) -> String {
    let expected: Vec<&str> = values.iter().map(|v| v.0).collect();
    let mut sorted = values.to_vec();
    sorted.sort_by(|a, b| b.1.total_cmp(&a.1));
    let measured: Vec<String> = sorted
        .iter()
        .map(|(name, v)| format!("{name} {}", sig(*v, 3)))
        .collect();
    if in_order(values) {
        format!("{what}: {}, the expected order", measured.join(" > "))
    } else {
        format!(
            "{what}: {}, not the expected order {}",
            measured.join(" > "),
            expected.join(" > ")
        )
    }
}

/// A fitted slope against two reference rates: `-1.36, nearer -1.5 than -1`.
pub fn nearer(slope: f64, a: f64, b: f64) -> String {
    let (near, far) = if (slope - a).abs() <= (slope - b).abs() {
        (a, b)
    } else {
        (b, a)
    };
    format!("{}, nearer {near} than {far}", sig(slope, 3))
}

/// Fitted slopes against stated rates, `(name, slope, rate)` a row: which are within `tol`
/// of their rate, which are steeper and which shallower, each with its value.
pub fn slopes_against_rates(rows: &[(&str, Option<f64>, f64)], tol: f64) -> String {
    let fitted: Vec<(&str, f64, f64)> = rows
        .iter()
        .filter_map(|&(name, s, rate)| s.map(|s| (name, s, rate)))
        .collect();
    let pick = |keep: &dyn Fn(f64, f64) -> bool| -> Vec<String> {
        fitted
            .iter()
            .filter(|&&(_, s, rate)| keep(s, rate))
            .map(|&(name, s, rate)| format!("{name} ({} against {rate})", sig(s, 3)))
            .collect()
    };
    let close = pick(&|s, r| (s - r).abs() <= tol);
    let steeper = pick(&|s, r| s < r - tol);
    let shallower = pick(&|s, r| s > r + tol);
    let mut s = format!(
        "{} fitted slopes are within {tol} of the stated rate",
        n_of_m(close.len(), fitted.len())
    );
    if !close.is_empty() && close.len() < fitted.len() {
        s.push_str(&format!(": {}", joined(&close)));
    }
    if !steeper.is_empty() {
        s.push_str(&format!("; steeper: {}", joined(&steeper)));
    }
    if !shallower.is_empty() {
        s.push_str(&format!("; shallower: {}", joined(&shallower)));
    }
    if fitted.len() < rows.len() {
        s.push_str(&format!(
            "; {} curves have too few usable points for a fit",
            rows.len() - fitted.len()
        ));
    }
    s.push('.');
    s
}

/// `In n of m THINGS, WHAT` (or `all m`, `none of the m`).
pub fn count(n: usize, m: usize, things: &str, what: &str) -> String {
    format!("In {} {things}, {what}", n_of_m(n, m))
}

/// How `a` compares with `b` as a factor: `3.2 times lower`, `1.5 times higher`, `equal`.
pub fn factor(a: f64, b: f64) -> String {
    if a == b {
        "equal".to_owned()
    } else if a < b && a > 0.0 {
        format!("{} times lower", sig(b / a, 3))
    } else if a > b && b > 0.0 {
        format!("{} times higher", sig(a / b, 3))
    } else if a < b {
        "lower".to_owned()
    } else {
        "higher".to_owned()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn agreement_counts_the_rows_within_k_standard_errors() {
        // The report's variance rows: 1.4, 0.08 and 0.97 standard errors apart.
        let rows = [
            ("jittered", 7.96e-6, 6.27e-6, 1.2e-6),
            ("Poisson disk", 1.55e-5, 1.53e-5, 2.4e-6),
            ("blue noise", 3.70e-6, 3.13e-6, 5.9e-7),
        ];
        let s = agreement(&rows, 2.0);
        assert!(s.contains("within 2 standard errors in all 3 rows"), "{s}");
        assert!(s.contains("jittered 1.41"), "{s}");
        assert!(!s.contains("differ"), "{s}");
        // Where a row is 5 standard errors off, the sentence says so and names it.
        let rows = [
            ("jittered", 7.96e-6, 1.96e-6, 1.2e-6),
            ("Poisson disk", 1.55e-5, 1.53e-5, 2.4e-6),
            ("blue noise", 3.70e-6, 3.13e-6, 5.9e-7),
        ];
        let s = agreement(&rows, 2.0);
        assert!(s.contains("in 2 of 3 rows"), "{s}");
        assert!(s.contains("jittered 5.00"), "{s}");
        assert!(
            s.contains("differ by more than 2 standard errors for jittered."),
            "{s}"
        );
        // None agree; a zero standard error with a difference is infinitely far.
        let s = agreement(&[("a", 1.0, 2.0, 0.0), ("b", 1.0, 3.0, 0.1)], 2.0);
        assert!(s.contains("in none of the 2 rows"), "{s}");
        assert!(s.contains("for a and b."), "{s}");
        let s = agreement(&[("a", 1.0, f64::NAN, 0.1)], 2.0);
        assert!(s.contains("none of the 1"), "{s}");
    }

    #[test]
    fn order_states_the_measured_order_and_whether_it_is_the_expected_one() {
        let kept = order(
            "mean D*",
            &[
                ("independent", 0.149),
                ("stratified", 0.0832),
                ("LP", 0.041),
            ],
        );
        assert_eq!(
            kept,
            "mean D*: independent 0.149 > stratified 0.0832 > LP 0.0410, the expected order"
        );
        let broken = order(
            "mean D*",
            &[("independent", 0.07), ("stratified", 0.0832), ("LP", 0.041)],
        );
        assert_eq!(
            broken,
            "mean D*: stratified 0.0832 > independent 0.0700 > LP 0.0410, not the expected \
             order independent > stratified > LP"
        );
        // A tie is not the strict order.
        assert!(!in_order(&[("a", 1.0), ("b", 1.0)]));
    }

    #[test]
    fn slopes_are_compared_with_their_values() {
        assert_eq!(nearer(-1.36, -1.5, -1.0), "-1.36, nearer -1.5 than -1");
        assert_eq!(nearer(-1.2, -1.5, -1.0), "-1.20, nearer -1 than -1.5");
        let rows = [
            ("MC", Some(-0.51), -0.5),
            ("Sobol'", Some(-2.0), -1.0),
            ("Owen", Some(-1.36), -1.5),
        ];
        let s = slopes_against_rates(&rows, 0.25);
        assert_eq!(
            s,
            "2 of 3 fitted slopes are within 0.25 of the stated rate: MC (-0.510 against \
             -0.5) and Owen (-1.36 against -1.5); steeper: Sobol' (-2.00 against -1)."
        );
        // All within: no list of exceptions; a shallower slope is named as such.
        let s = slopes_against_rates(&rows[..1], 0.25);
        assert_eq!(s, "all 1 fitted slopes are within 0.25 of the stated rate.");
        let s = slopes_against_rates(&[("MC", Some(-0.1), -0.5), ("x", None, -1.0)], 0.25);
        assert!(s.starts_with("none of the 1 fitted slopes"), "{s}");
        assert!(s.contains("shallower: MC (-0.100 against -0.5)"), "{s}");
        assert!(s.contains("1 curves have too few usable points"), "{s}");
    }

    #[test]
    fn counts_and_factors() {
        assert_eq!(count(6, 6, "grids", "x"), "In all 6 grids, x");
        assert_eq!(count(5, 6, "grids", "x"), "In 5 of 6 grids, x");
        assert_eq!(count(0, 6, "grids", "x"), "In none of the 6 grids, x");
        assert_eq!(factor(1.0, 3.2), "3.20 times lower");
        assert_eq!(factor(3.0, 2.0), "1.50 times higher");
        assert_eq!(factor(2.0, 2.0), "equal");
        assert_eq!(factor(0.0, 2.0), "lower");
    }
}
