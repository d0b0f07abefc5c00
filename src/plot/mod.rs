//! Plot helpers (plotters, bitmap backend): heat maps with a colour bar, line plots and contact
//! maps. Every PNG is drawn in memory and written atomically with
//! [`surrogate::atomic_file::write_atomic`]. Text uses the bundled DejaVu Sans, registered once by
//! [`register_fonts`].

pub mod chart;
mod colormap;
mod contact_map;
pub mod figures;
pub mod friction;
mod heat_map;
mod line_plot;
pub mod tolerance;
pub mod work_precision;
pub mod yield_curve;

pub use colormap::viridis;
pub use contact_map::{contact_map, ContactMapData};
pub use heat_map::{heat_map, HeatMap};
pub use line_plot::{line_plot, stacked_line_plots, LinePlot, Series};

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

/// Draws with `draw` into an RGB image of `size` pixels and writes it as a PNG at `path`
/// atomically ([`surrogate::atomic_file::write_atomic`]: temporary sibling, then rename), encoded with the
/// best zlib compression and adaptive filtering (plotters' own encoder compresses fast and
/// poorly: a 1150×960 contact map took ~1.4 MB); if that is still above 250 kB the image is
/// re-encoded with a 256-colour palette (`quantize`), which keeps every figure ≤ 300 kB.
pub fn png_atomic<F>(path: &Path, size: (u32, u32), draw: F) -> Result<()>
where
    F: FnOnce(
        plotters::drawing::DrawingArea<plotters::prelude::BitMapBackend<'_>, plotters::coord::Shift>,
    ) -> Result<()>,
{
    use plotters::prelude::*;
    register_fonts();
    let mut buf = vec![255u8; size.0 as usize * size.1 as usize * 3];
    {
        let root = BitMapBackend::with_buffer(&mut buf, size).into_drawing_area();
        root.fill(&WHITE)
            .map_err(|e| anyhow::anyhow!("drawing {}: {e}", path.display()))?;
        draw(root.clone())?;
        root.present()
            .map_err(|e| anyhow::anyhow!("drawing {}: {e}", path.display()))?;
    }
    let mut bytes =
        encode_png(&buf, size, None).with_context(|| format!("encoding {}", path.display()))?;
    if bytes.len() > MAX_RGB_PNG_BYTES {
        let (indices, palette) = quantize(&buf);
        bytes = encode_png(&indices, size, Some(&palette))
            .with_context(|| format!("encoding {}", path.display()))?;
    }
    surrogate::atomic_file::write_atomic(path, &bytes)
        .with_context(|| format!("writing {}", path.display()))
}

/// An RGB PNG larger than this (bytes) is re-encoded with a 256-colour palette ([`quantize`]).
const MAX_RGB_PNG_BYTES: usize = 250_000;

/// Encodes 8-bit RGB pixels (`palette` = None) or palette indices as a PNG, best compression.
fn encode_png(data: &[u8], size: (u32, u32), palette: Option<&[u8]>) -> Result<Vec<u8>> {
    let mut bytes = Vec::new();
    {
        let mut enc = png::Encoder::new(&mut bytes, size.0, size.1);
        match palette {
            None => enc.set_color(png::ColorType::Rgb),
            Some(p) => {
                enc.set_color(png::ColorType::Indexed);
                enc.set_palette(p.to_vec());
            }
        }
        enc.set_depth(png::BitDepth::Eight);
        enc.set_compression(png::Compression::Best);
        enc.set_adaptive_filter(png::AdaptiveFilterType::Adaptive);
        let mut w = enc.write_header()?;
        w.write_image_data(data)?;
    }
    Ok(bytes)
}

/// Popularity colour quantization of 8-bit RGB pixels: the (up to) 256 most frequent colours
/// (ties broken by colour value, so deterministic) form the palette; every pixel takes the
/// nearest palette colour (squared RGB distance). Exact when the image has ≤ 256 colours;
/// otherwise only anti-aliasing shades and fine gradients are snapped. Returns (indices, palette
/// as RGB triplets). Cost: O(pixels + distinct colours · 256).
fn quantize(rgb: &[u8]) -> (Vec<u8>, Vec<u8>) {
    use std::collections::HashMap;
    let mut count: HashMap<[u8; 3], u32> = HashMap::new();
    for p in rgb.chunks_exact(3) {
        *count.entry([p[0], p[1], p[2]]).or_insert(0) += 1;
    }
    let mut by_freq: Vec<([u8; 3], u32)> = count.into_iter().collect();
    by_freq.sort_by(|a, b| b.1.cmp(&a.1).then(a.0.cmp(&b.0)));
    let palette: Vec<[u8; 3]> = by_freq.iter().take(256).map(|c| c.0).collect();
    let nearest: HashMap<[u8; 3], u8> = by_freq
        .iter()
        .map(|&(c, _)| {
            let mut best = (u32::MAX, 0u8);
            for (k, p) in palette.iter().enumerate() {
                let d: u32 = (0..3)
                    .map(|i| (c[i] as i32 - p[i] as i32).pow(2) as u32)
                    .sum();
                if d < best.0 {
                    best = (d, k as u8);
                }
            }
            (c, best.1)
        })
        .collect();
    let idx = rgb
        .chunks_exact(3)
        .map(|p| nearest[&[p[0], p[1], p[2]]])
        .collect();
    (idx, palette.concat())
}

/// Converts a plotters error into anyhow with context.
pub(crate) fn perr<E: std::fmt::Display>(what: &str) -> impl FnOnce(E) -> anyhow::Error + '_ {
    move |e| anyhow::anyhow!("plotting {what}: {e}")
}
