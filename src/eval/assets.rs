//! Asset paths (meshes, images) named in a scene: found by the asset service's one search order
//! (`assets::search`) and required to exist, so `rtc check` catches a missing file before any
//! ray is traced.

use std::path::PathBuf;

use crate::source::Span;

use super::error::R;
use super::host::Host;

/// The file `rel` names from the current module (a `what` file: "mesh", "image"); an error
/// naming every place looked at if there is none.
pub(crate) fn existing(it: &dyn Host, rel: &str, span: Span, what: &str) -> R<PathBuf> {
    crate::assets::search::find(it.dir(), rel).map_err(|missing| {
        let file = it.file_path();
        missing.diagnostic(span, what, file).into()
    })
}
