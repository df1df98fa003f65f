//! What every plot shares: the embedded font, the two file formats, the size.

use std::path::{Path, PathBuf};

use std::ops::Range;

use anyhow::Context;

use crate::recording::note_finished;
use plotters::chart::MeshStyle;
use plotters::coord::Shift;
use plotters::coord::types::RangedCoordf64;
use plotters::prelude::*;

const FONT: &[u8] = include_bytes!("../../assets/fonts/DejaVuSans.ttf");

/// Plot size (pixels; SVG user units).
pub const SIZE: (u32, u32) = (1024, 640);

/// Draws the same picture into `base.png` and `base.svg`, returning both paths. Each is
/// drawn under a partial name (`base.partial.png`, so that the format still shows) and
/// given its final name only when complete; a failure names the file.
pub fn png_and_svg(
    base: &Path,
    draw_png: impl Fn(DrawingArea<BitMapBackend, Shift>) -> anyhow::Result<()>,
    draw_svg: impl Fn(DrawingArea<SVGBackend, Shift>) -> anyhow::Result<()>,
) -> anyhow::Result<Vec<PathBuf>> {
    plotters::style::register_font("sans-serif", FontStyle::Normal, FONT)
        .map_err(|_| anyhow::anyhow!("the embedded font cannot be read"))?;
    // Appended, not `with_extension`: a base such as `waterfall-2.712_N_m` keeps its dot.
    let named = |extension: &str| PathBuf::from(format!("{}.{extension}", base.display()));
    let partial =
        |extension: &str| PathBuf::from(format!("{}.partial.{extension}", base.display()));
    let (png, svg) = (named("png"), named("svg"));
    let (png_partial, svg_partial) = (partial("png"), partial("svg"));
    draw_png(BitMapBackend::new(&png_partial, SIZE).into_drawing_area())
        .with_context(|| format!("cannot write {}", png.display()))?;
    commit(&png_partial, &png)?;
    draw_svg(SVGBackend::new(&svg_partial, SIZE).into_drawing_area())
        .with_context(|| format!("cannot write {}", svg.display()))?;
    commit(&svg_partial, &svg)?;
    Ok(vec![png, svg])
}

/// Gives the finished drawing `partial` its final name `path`.
fn commit(partial: &Path, path: &Path) -> anyhow::Result<()> {
    std::fs::rename(partial, path).with_context(|| format!("cannot name {}", path.display()))?;
    note_finished(path);
    Ok(())
}

/// A plotters error as an anyhow error naming what was drawn.
pub fn draw_error<E: std::fmt::Debug>(what: &'static str) -> impl Fn(E) -> anyhow::Error {
    move |error| anyhow::anyhow!("drawing the {what}: {error:?}")
}

/// Linear axes in x and y, as every plot here draws.
pub type Axes<'a, DB> = ChartContext<'a, DB, Cartesian2d<RangedCoordf64, RangedCoordf64>>;

/// Clears `root` to white and sets up `title` and axes over `x` × `y`.
pub fn axes<'a, DB: DrawingBackend>(
    root: &'a DrawingArea<DB, Shift>,
    title: &str,
    x: Range<f64>,
    y: Range<f64>,
) -> anyhow::Result<Axes<'a, DB>> {
    axes_with_right_area(root, title, x, y, 0)
}

/// As [`axes`], with `right_px` pixels on the right for a second vertical axis.
pub fn axes_with_right_area<'a, DB: DrawingBackend>(
    root: &'a DrawingArea<DB, Shift>,
    title: &str,
    x: Range<f64>,
    y: Range<f64>,
    right_px: u32,
) -> anyhow::Result<Axes<'a, DB>> {
    let err = draw_error("axes");
    root.fill(&WHITE).map_err(&err)?;
    let size = title_size(title, root.dim_in_pixel().0);
    ChartBuilder::on(root)
        .caption(title, ("sans-serif", size))
        .margin(12)
        // Room for the last x label and for labels drawn at the right edge.
        .margin_right(36)
        .x_label_area_size(44)
        .y_label_area_size(70)
        .right_y_label_area_size(right_px)
        .build_cartesian_2d(x, y)
        .map_err(err)
}

/// The title's type size (pt): 20, smaller for a title that would not fit `width_px`
/// (about 0.55 em a character in DejaVu Sans), never below 11.
fn title_size(title: &str, width_px: u32) -> f64 {
    let chars = title.chars().count().max(1) as f64;
    (0.95 * f64::from(width_px) / (0.55 * chars)).clamp(11.0, 20.0)
}

/// Draws the grid and the axis descriptions; `style` adjusts the grid (label counts,
/// grid lines left out).
pub fn mesh<DB: DrawingBackend>(
    chart: &mut Axes<DB>,
    (x_desc, y_desc): (&str, &str),
    style: impl FnOnce(&mut MeshStyle<RangedCoordf64, RangedCoordf64, DB>),
) -> anyhow::Result<()> {
    let mut mesh = chart.configure_mesh();
    mesh.x_desc(x_desc)
        .y_desc(y_desc)
        .label_style(("sans-serif", 14));
    style(&mut mesh);
    mesh.draw().map_err(draw_error("grid"))
}

/// Share of a plot's height a legend of `entries` lines takes (13-pt lines on ~560 px),
/// for the headroom that keeps it off the curves.
pub fn legend_share(entries: usize) -> f64 {
    ((entries as f64 * 18.0 + 20.0) / 560.0).min(0.6)
}

/// Draws the legend of the labelled series at `position` (a corner the curves leave free).
pub fn legend<'a, DB: DrawingBackend + 'a>(
    chart: &mut Axes<'a, DB>,
    position: SeriesLabelPosition,
) -> anyhow::Result<()> {
    chart
        .configure_series_labels()
        .position(position)
        .background_style(WHITE.mix(0.85))
        .border_style(BLACK)
        .label_font(("sans-serif", 13))
        .draw()
        .map_err(draw_error("legend"))
}
