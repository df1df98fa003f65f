//! Plots as the thesis draws them, as PNG and SVG (plotters with an embedded font, so no
//! system font libraries are needed).

pub mod canvas;
pub mod scope;
pub mod spectrum;
pub mod survey;

pub use scope::write_scope_plots;
pub use spectrum::{SpectrumPlot, write_spectrum_plots};
pub use survey::{SurveyPoint, write_survey_plots};
