//! SVG drawing of toolpaths.

use cycleref::Move;
use cycleref_spec::reader::G76Call;

/// Draws the cycles as an SVG document.
pub fn svg(_name: &str, _cycles: &[(G76Call, Vec<Move>)]) -> Result<String, String> {
    Err("plot: not yet available".into())
}
