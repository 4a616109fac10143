//! TODO

use super::{Ctx, Section};
use crate::Failure;

/// The slides of this group.
pub fn sections(_ctx: &Ctx) -> Result<Vec<Section>, Failure> {
    Ok(vec![])
}

/// The slides of this group.
pub fn variance_sections(_ctx: &Ctx) -> Result<Vec<Section>, Failure> {
    Ok(vec![])
}
