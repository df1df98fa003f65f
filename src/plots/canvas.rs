//! What every plot shares: the embedded font, the two file formats, the size.

use std::path::{Path, PathBuf};

use plotters::coord::Shift;
use plotters::prelude::*;

const FONT: &[u8] = include_bytes!("../../assets/fonts/DejaVuSans.ttf");

/// Plot size (pixels; SVG user units).
pub const SIZE: (u32, u32) = (1024, 640);

/// Draws the same picture into `base.png` and `base.svg`, returning both paths.
pub fn png_and_svg(
    base: &Path,
    draw_png: impl Fn(DrawingArea<BitMapBackend, Shift>) -> anyhow::Result<()>,
    draw_svg: impl Fn(DrawingArea<SVGBackend, Shift>) -> anyhow::Result<()>,
) -> anyhow::Result<Vec<PathBuf>> {
    plotters::style::register_font("sans-serif", FontStyle::Normal, FONT)
        .map_err(|_| anyhow::anyhow!("the embedded font cannot be read"))?;
    // Appended, not `with_extension`: a base such as `waterfall-2.712_N_m` keeps its dot.
    let png = PathBuf::from(format!("{}.png", base.display()));
    let svg = PathBuf::from(format!("{}.svg", base.display()));
    draw_png(BitMapBackend::new(&png, SIZE).into_drawing_area())?;
    draw_svg(SVGBackend::new(&svg, SIZE).into_drawing_area())?;
    Ok(vec![png, svg])
}

/// A plotters error as an anyhow error naming what was drawn.
pub fn draw_error<E: std::fmt::Debug>(what: &'static str) -> impl Fn(E) -> anyhow::Error {
    move |error| anyhow::anyhow!("drawing the {what}: {error:?}")
}
