//! Plots as the thesis draws them, as PNG and SVG (plotters with an embedded font, so no
//! system font libraries are needed).
//!
//! Files: one drawing to PNG and SVG (`canvas.rs`: embedded DejaVu font, a title's size
//! fitted to the width): `spectrum.rs` (orders marked, labels kept clear of the legend),
//! `scope.rs` (a µε axis where the signal has a strain calibration), `survey.rs`,
//! `frequency_map.rs`, `waterfall.rs`, `regime_map.rs`, `bifurcation.rs`,
//! `impact_raster.rs`, `convergence.rs`, `synchronous_average.rs` (a gear's averaged
//! revolution, its faulted tooth marked).

pub(crate) mod bifurcation;
pub(crate) mod canvas;
pub(crate) mod convergence;
pub(crate) mod frequency_map;
pub(crate) mod impact_raster;
pub(crate) mod regime_map;
pub(crate) mod scope;
pub(crate) mod spectrum;
pub(crate) mod survey;
pub(crate) mod synchronous_average;
pub(crate) mod waterfall;

pub use bifurcation::{SectionColumn, write_bifurcation};
pub use convergence::{SearchPoint, write_convergence};
pub use frequency_map::{SpeedLines, write_frequency_map};
pub use impact_raster::{RasterImpact, write_impact_raster};
pub use regime_map::{RegimeCell, write_regime_map};
pub use scope::{ScopeScales, write_scope_plots};
pub use spectrum::{SpectrumPlot, write_spectrum_plots};
pub use survey::{SurveyPoint, write_survey_plots};
pub use synchronous_average::{AveragePlot, write_synchronous_average};
pub use waterfall::{WaterfallTrace, write_waterfall};
