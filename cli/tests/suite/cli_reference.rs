//! docs/cli.md against the command's own help: every command that `qmckit --help` lists has
//! a section `## \`qmckit CMD\``, and every long option and every possible value that
//! `qmckit CMD --help` lists (subcommands too) is written in code in that section or in a
//! section it links to (`[...](#anchor)`), so the reference cannot drift from the code.

use std::collections::{BTreeMap, BTreeSet};

use crate::common::cli::run;

/// The help text of `qmckit ARGS --help`.
fn help(args: &[&str]) -> String {
    let out = run(&[args, &["--help"]].concat(), "");
    assert_eq!(out.status.code(), Some(0), "{args:?}");
    String::from_utf8(out.stdout).unwrap()
}

/// The names under `Commands:` (without clap's `help`).
fn commands(help: &str) -> Vec<String> {
    help.lines()
        .skip_while(|l| l.trim() != "Commands:")
        .skip(1)
        .take_while(|l| !l.trim().is_empty())
        .filter_map(|l| l.split_whitespace().next())
        .filter(|name| *name != "help")
        .map(str::to_owned)
        .collect()
}

/// The long options of the `Options:` block (`--name`), without `--help` and `--version`.
/// The block's lines are indented (or empty); the text after the options starts at the
/// margin and is not read.
fn long_options(help: &str) -> Vec<String> {
    help.lines()
        .skip_while(|l| l.trim() != "Options:")
        .skip(1)
        .take_while(|l| l.is_empty() || l.starts_with(' '))
        .map(str::trim_start)
        .filter_map(|l| {
            // `--name ...` or `-x, --name ...`; not a possible value (`- name: ...`).
            let rest = match l.as_bytes() {
                [b'-', b'-', ..] => l,
                [b'-', c, b',', b' ', b'-', b'-', ..] if c.is_ascii_alphanumeric() => &l[4..],
                _ => return None,
            };
            let flag = rest.split([' ', ',', '=', '<']).next()?;
            Some(flag.to_owned())
        })
        .filter(|f| f != "--help" && f != "--version")
        .collect()
}

/// The possible values of every argument: `- name: ...` lines after `Possible values:`, and
/// the short form `[possible values: a, b]`.
fn possible_values(help: &str) -> Vec<String> {
    let mut values = Vec::new();
    let mut in_list = false;
    for line in help.lines() {
        let t = line.trim();
        if t == "Possible values:" {
            in_list = true;
            continue;
        }
        if in_list {
            match t.strip_prefix("- ") {
                Some(item) => {
                    let name = item.split(':').next().unwrap_or(item).trim();
                    values.push(name.to_owned());
                    continue;
                }
                None => in_list = false,
            }
        }
        if let Some(start) = t.find("[possible values: ") {
            let rest = &t[start + "[possible values: ".len()..];
            let list = &rest[..rest.find(']').unwrap_or(rest.len())];
            values.extend(list.split(", ").map(|v| v.trim().to_owned()));
        }
    }
    values
}

/// GitHub's anchor of a heading: lower case, letters, digits, `-` and `_` kept, spaces to
/// `-`, everything else dropped.
fn anchor(heading: &str) -> String {
    heading
        .trim()
        .to_lowercase()
        .chars()
        .filter_map(|c| match c {
            ' ' => Some('-'),
            c if c.is_alphanumeric() || c == '-' || c == '_' => Some(c),
            _ => None,
        })
        .collect()
}

/// The `## ` sections of the document by anchor (`###` and deeper belong to their `##`).
fn sections(doc: &str) -> BTreeMap<String, String> {
    let mut out = BTreeMap::new();
    let mut current = String::new();
    let mut body = String::new();
    for line in doc.lines() {
        if let Some(h) = line.strip_prefix("## ") {
            out.insert(std::mem::take(&mut current), std::mem::take(&mut body));
            current = anchor(h);
        }
        body.push_str(line);
        body.push('\n');
    }
    out.insert(current, body);
    out
}

/// The words written in code in `text`: in `` `spans` `` and in fenced blocks, split at
/// everything but letters, digits, `-` and `_` (so `--seed` and `fast-owen-lk` are words,
/// and `--seed` is not found inside `--seeds`).
fn code_words(text: &str) -> BTreeSet<String> {
    let mut code = String::new();
    let mut fenced = false;
    for line in text.lines() {
        if line.trim_start().starts_with("```") {
            fenced = !fenced;
            continue;
        }
        if fenced {
            code.push_str(line);
            code.push('\n');
        } else {
            for (k, part) in line.split('`').enumerate() {
                if k % 2 == 1 {
                    code.push_str(part);
                    code.push('\n');
                }
            }
        }
    }
    code.split(|c: char| !(c.is_alphanumeric() || c == '-' || c == '_'))
        .filter(|w| !w.is_empty())
        .map(str::to_owned)
        .collect()
}

/// The code words of section `id` and of every section it links to (`](#anchor)`).
fn words_for(sections: &BTreeMap<String, String>, id: &str) -> BTreeSet<String> {
    let own = sections
        .get(id)
        .unwrap_or_else(|| panic!("docs/cli.md has no section '## `qmckit ...`' for #{id}"));
    let mut words = code_words(own);
    for link in own.split("](#").skip(1) {
        let target = &link[..link.find(')').unwrap_or(0)];
        let linked = sections
            .get(target)
            .unwrap_or_else(|| panic!("#{id} links to #{target}, which is no section"));
        words.extend(code_words(linked));
    }
    words
}

#[test]
fn the_command_reference_covers_the_help() {
    let doc = std::fs::read_to_string(concat!(env!("CARGO_MANIFEST_DIR"), "/../docs/cli.md"))
        .expect("docs/cli.md");
    let sections = sections(&doc);
    let all = code_words(&doc);
    let top = help(&[]);
    let cmds = commands(&top);
    assert!(cmds.len() >= 11, "{cmds:?}");
    let mut missing = Vec::new();
    for flag in ["--help", "--version"] {
        if !all.contains(flag) {
            missing.push(format!("{flag} (qmckit --help)"));
        }
    }
    for cmd in &cmds {
        let id = anchor(&format!("`qmckit {cmd}`"));
        let words = words_for(&sections, &id);
        let text = help(&[cmd]);
        // A command with subcommands (mask): each subcommand's name and help too.
        let mut helps = vec![(cmd.clone(), text.clone())];
        for sub in commands(&text) {
            if !words.contains(&sub) {
                missing.push(format!("{sub} (qmckit {cmd} --help) in #{id}"));
            }
            helps.push((format!("{cmd} {sub}"), help(&[cmd, &sub])));
        }
        for (name, text) in &helps {
            let options = long_options(text);
            let values = possible_values(text);
            for item in options.iter().chain(&values) {
                if !words.contains(item) {
                    missing.push(format!("{item} (qmckit {name} --help) in #{id}"));
                }
            }
        }
    }
    assert!(
        missing.is_empty(),
        "docs/cli.md does not mention:\n  {}",
        missing.join("\n  ")
    );
}

#[test]
fn the_help_parsers_read_clap_output() {
    let points = help(&["points"]);
    let options = long_options(&points);
    for flag in [
        "--start",
        "--scramble",
        "--format",
        "--warp",
        "--max-seconds",
    ] {
        assert!(options.iter().any(|o| o == flag), "{flag}: {options:?}");
    }
    assert!(!options.iter().any(|o| o == "--help"));
    // Options only: the text after them names options in prose, and is not read.
    let clean = |o: &String| o[2..].chars().all(|c| c.is_ascii_lowercase() || c == '-');
    assert!(options.iter().all(clean), "{options:?}");
    assert!(long_options(&help(&["spectrum"])).iter().all(clean));
    let values = possible_values(&points);
    for v in [
        "halton",
        "pmj02bn",
        "shift-tent",
        "decimal",
        "u32",
        "box-muller",
    ] {
        assert!(values.iter().any(|x| x == v), "{v}: {values:?}");
    }
    assert_eq!(commands(&help(&["mask"])), ["void-and-cluster"]);
    assert_eq!(anchor("`qmckit points`"), "qmckit-points");
    assert_eq!(anchor("Samplers (`SAMPLER`)"), "samplers-sampler");
    let words = code_words("a `--seeds` b\n```\nqmckit x --format u32|csv\n```\n");
    assert!(words.contains("--seeds") && !words.contains("--seed"));
    assert!(words.contains("u32") && words.contains("csv") && !words.contains("a"));
}
