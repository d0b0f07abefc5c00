//! Plot helpers (plotters, bitmap backend): heat maps with a colour bar, line plots and contact
//! maps. Every PNG is drawn to a temporary sibling and renamed into place (atomic, like
//! [`crate::output::write_atomic`]). Text uses the bundled DejaVu Sans, registered once by
//! [`register_fonts`].

mod colormap;
mod contact_map;
mod heat_map;
mod line_plot;

pub use colormap::viridis;
pub use contact_map::{contact_map, ContactMapData};
pub use heat_map::{heat_map, HeatMap};
pub use line_plot::{line_plot, line_plot_area, LinePlot, Series};

use anyhow::{Context, Result};
use std::path::Path;
use std::sync::Once;

/// Font family name used by every plot.
pub const FONT: &str = "sans-serif";

/// Registers the bundled DejaVu Sans as the `sans-serif` family (idempotent).
pub fn register_fonts() {
    static ONCE: Once = Once::new();
    ONCE.call_once(|| {
        let bytes: &'static [u8] = include_bytes!("../assets/DejaVuSans.ttf");
        for style in [
            plotters::style::FontStyle::Normal,
            plotters::style::FontStyle::Bold,
        ] {
            // The font is compiled in and known to be valid.
            let _ = plotters::style::register_font(FONT, style, bytes);
        }
    });
}

/// Draws with `draw` into a PNG of `size` pixels at `path`, atomically (temporary sibling,
/// then rename). Creates the parent directory.
pub fn png_atomic<F>(path: &Path, size: (u32, u32), draw: F) -> Result<()>
where
    F: FnOnce(
        plotters::drawing::DrawingArea<plotters::prelude::BitMapBackend<'_>, plotters::coord::Shift>,
    ) -> Result<()>,
{
    use plotters::prelude::*;
    register_fonts();
    if let Some(dir) = path.parent() {
        if !dir.as_os_str().is_empty() {
            std::fs::create_dir_all(dir)
                .with_context(|| format!("creating directory {}", dir.display()))?;
        }
    }
    // Keep the .png extension on the temporary file: the encoder picks the format from it.
    let tmp = path.with_file_name(format!(
        ".{}.{}.tmp.png",
        path.file_name().and_then(|n| n.to_str()).unwrap_or("plot"),
        std::process::id()
    ));
    {
        let root = BitMapBackend::new(&tmp, size).into_drawing_area();
        root.fill(&WHITE)
            .map_err(|e| anyhow::anyhow!("drawing {}: {e}", path.display()))?;
        draw(root.clone())?;
        root.present()
            .map_err(|e| anyhow::anyhow!("writing {}: {e}", tmp.display()))?;
    }
    std::fs::rename(&tmp, path)
        .with_context(|| format!("renaming {} to {}", tmp.display(), path.display()))?;
    Ok(())
}

/// Converts a plotters error into anyhow with context.
pub(crate) fn perr<E: std::fmt::Display>(what: &str) -> impl FnOnce(E) -> anyhow::Error + '_ {
    move |e| anyhow::anyhow!("plotting {what}: {e}")
}
