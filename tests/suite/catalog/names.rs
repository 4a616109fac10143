//! Every name and alias of the five lists resolves to its entry, and no two collide.

use qmckit::catalog::{
    self, CatalogError, INTEGRANDS, List, MEASURES, PIXEL_SAMPLERS, RANDOMIZERS, SAMPLERS,
    same_name,
};

fn check_list<K: PartialEq + std::fmt::Debug>(
    list: List,
    table: &'static [catalog::Entry<K>],
    find: fn(&str) -> Result<&'static catalog::Entry<K>, CatalogError>,
) {
    assert_eq!(list.len(), table.len());
    assert_eq!(
        list.names().collect::<Vec<_>>(),
        table.iter().map(|e| e.name).collect::<Vec<_>>()
    );
    let mut all: Vec<(&str, usize)> = Vec::new();
    for (k, e) in table.iter().enumerate() {
        // Canonical names are kebab-case.
        assert!(
            e.name
                .bytes()
                .all(|b| b.is_ascii_lowercase() || b.is_ascii_digit() || b == b'-'),
            "{}",
            e.name
        );
        assert!(!e.summary.is_empty() && !e.math.is_empty() && e.item.starts_with("qmckit::"));
        for a in e.aliases {
            assert!(
                !a.source.is_empty(),
                "{}: alias {} has no source",
                e.name,
                a.name
            );
        }
        for name in e.names() {
            let found = find(name).unwrap_or_else(|err| panic!("{name}: {err}"));
            assert_eq!(found.kind, e.kind, "{name}");
            assert!(std::ptr::eq(found, e), "{name}");
            let upper = name.to_ascii_uppercase().replace('-', "_");
            assert_eq!(find(&upper).unwrap().kind, e.kind, "{upper}");
            all.push((name, k));
        }
    }
    // Unique across entries and aliases, under the comparison names resolve by.
    for (i, (a, ka)) in all.iter().enumerate() {
        for (b, kb) in &all[i + 1..] {
            assert!(
                !same_name(a, b),
                "{list:?}: {a:?} ({ka}) and {b:?} ({kb}) collide"
            );
        }
    }
    let err = find("no-such-thing").unwrap_err();
    let text = err.to_string();
    assert!(text.contains("\"no-such-thing\""), "{text}");
    for e in table {
        assert!(text.contains(e.name), "{text} lacks {}", e.name);
    }
}

#[test]
fn every_name_and_alias_resolves_to_its_entry() {
    check_list(List::Samplers, SAMPLERS, catalog::sampler);
    check_list(List::Randomizers, RANDOMIZERS, catalog::randomizer);
    check_list(List::PixelSamplers, PIXEL_SAMPLERS, catalog::pixel_sampler);
    check_list(List::Measures, MEASURES, catalog::measure);
    check_list(List::Integrands, INTEGRANDS, catalog::integrand);
    // The names other tools use.
    for (name, want) in [
        ("PermuteDigits", "xor"),
        ("digital-shift", "xor"),
        ("FastOwen", "fast-owen"),
        ("Owen", "owen"),
        ("None", "none"),
        ("LMS_DS", "lms"),
        ("NUS", "owen"),
        ("SHIFT", "shift"),
    ] {
        assert_eq!(catalog::randomizer(name).unwrap().name, want, "{name}");
    }
    for (name, want) in [
        ("jittered", "stratified"),
        ("LatinHypercube", "latin"),
        ("PoissonDisk", "poisson"),
        ("Sobol'", "sobol"),
        ("Halton", "halton"),
    ] {
        assert_eq!(catalog::sampler(name).unwrap().name, want, "{name}");
    }
    assert_eq!(catalog::measure("L2-star").unwrap().name, "l2-star");
    assert_eq!(catalog::measure("CD").unwrap().name, "cd");
    assert_eq!(catalog::pixel_sampler("sobol").unwrap().name, "image-sobol");
    // A long unknown name is cut, not refused.
    let long = "x".repeat(300);
    assert!(
        catalog::sampler(&long)
            .unwrap_err()
            .to_string()
            .contains("xxxx")
    );
}
