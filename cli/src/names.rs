//! Command-line values read from the library's catalog (`qmckit::catalog`): a sampler,
//! randomizer, pixel sampler, measure or integrand argument takes any name or alias of its
//! list (any case), and its help lists the canonical names with their one-line summaries,
//! so a new catalog entry shows up in every command without editing the command.

use std::ffi::OsStr;

use clap::builder::{PossibleValue, TypedValueParser};
use clap::error::{ContextKind, ContextValue, ErrorKind};
use qmckit::catalog::{self, CatalogError, Entry};

/// A clap value parser over one catalog list: the value is the entry the name names.
pub struct CatalogParser<K: 'static> {
    table: &'static [Entry<K>],
    lookup: fn(&str) -> Result<&'static Entry<K>, CatalogError>,
    /// The entries the command takes (the others are refused by name, in one line).
    keep: fn(&Entry<K>) -> bool,
    /// What the command is, for the refusal (`tvalue judges ...`).
    why: &'static str,
}

impl<K: 'static> CatalogParser<K> {
    /// Only the entries `keep` accepts are listed and taken; another catalog name is
    /// refused with `why` (what the command takes, in words).
    pub fn only(self, keep: fn(&Entry<K>) -> bool, why: &'static str) -> Self {
        CatalogParser { keep, why, ..self }
    }
}

impl<K: 'static> Clone for CatalogParser<K> {
    fn clone(&self) -> Self {
        CatalogParser {
            table: self.table,
            lookup: self.lookup,
            keep: self.keep,
            why: self.why,
        }
    }
}

/// The samplers (`catalog::SAMPLERS`).
pub fn samplers() -> CatalogParser<catalog::SamplerKind> {
    CatalogParser {
        table: catalog::SAMPLERS,
        lookup: catalog::sampler,
        keep: |_| true,
        why: "",
    }
}

/// The randomizers (`catalog::RANDOMIZERS`).
pub fn randomizers() -> CatalogParser<catalog::RandomizerKind> {
    CatalogParser {
        table: catalog::RANDOMIZERS,
        lookup: catalog::randomizer,
        keep: |_| true,
        why: "",
    }
}

/// The pixel samplers (`catalog::PIXEL_SAMPLERS`).
pub fn pixel_samplers() -> CatalogParser<catalog::PixelKind> {
    CatalogParser {
        table: catalog::PIXEL_SAMPLERS,
        lookup: catalog::pixel_sampler,
        keep: |_| true,
        why: "",
    }
}

/// The integrands (`catalog::INTEGRANDS`).
pub fn integrands() -> CatalogParser<catalog::IntegrandKind> {
    CatalogParser {
        table: catalog::INTEGRANDS,
        lookup: catalog::integrand,
        keep: |_| true,
        why: "",
    }
}

impl<K: Send + Sync + 'static> TypedValueParser for CatalogParser<K> {
    type Value = &'static Entry<K>;

    fn parse_ref(
        &self,
        cmd: &clap::Command,
        arg: Option<&clap::Arg>,
        value: &OsStr,
    ) -> Result<Self::Value, clap::Error> {
        let text = value.to_string_lossy();
        let found = (self.lookup)(&text).map_err(|e| e.to_string());
        let found = match found {
            Ok(entry) if !(self.keep)(entry) => Err(format!("{}: {}", entry.name, self.why)),
            other => other,
        };
        found.map_err(|e| {
            let mut err = clap::Error::new(ErrorKind::InvalidValue).with_cmd(cmd);
            if let Some(arg) = arg {
                err.insert(
                    ContextKind::InvalidArg,
                    ContextValue::String(arg.to_string()),
                );
            }
            err.insert(ContextKind::InvalidValue, ContextValue::String(e));
            err
        })
    }

    fn possible_values(&self) -> Option<Box<dyn Iterator<Item = PossibleValue> + '_>> {
        Some(Box::new(
            self.table
                .iter()
                .filter(|e| (self.keep)(e))
                .map(|e| PossibleValue::new(e.name).help(e.summary)),
        ))
    }
}

/// The command's message for a catalog error: the catalog's parameter names become the
/// command's flags (`dims` is `-d`, `points` `--total`, `base` `--base`, ...).
pub fn flag_text(e: &CatalogError) -> String {
    let text = e.to_string();
    match e {
        CatalogError::Parameter { entry, param, .. } => {
            let flag = flag(param);
            text.replacen(&format!("{entry}: {param}"), &format!("{entry}: {flag}"), 1)
        }
        CatalogError::Unused { param, .. } => {
            let flag = flag(param);
            text.replacen(
                &format!("{param} does not apply"),
                &format!("{flag} does not apply"),
                1,
            )
        }
        CatalogError::NotApplicable {
            randomizer,
            sampler,
            base,
            rule,
        } => {
            let base = base.map(|b| format!(" in base {b}")).unwrap_or_default();
            format!(
                "--scramble {randomizer} does not apply to {sampler}{base}: it applies to {rule}"
            )
        }
        _ => text,
    }
}

/// The command's flag for a catalog parameter name.
fn flag(param: &str) -> String {
    match param {
        "dims" => "-d".to_owned(),
        "points" => "--total".to_owned(),
        p if p.chars().all(|c| c.is_ascii_lowercase() || c == '-') => format!("--{p}"),
        p => p.to_owned(),
    }
}
