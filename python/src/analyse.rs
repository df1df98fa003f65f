//! `testrig.analyse`: the Fourier analyser (with its ADC, and an anti-alias filter if
//! asked) on any numpy array, with the ground truth of which lines are aliases.

use instruments::{FilterKind, Sampling, Window};
use numpy::{IntoPyArray, PyReadonlyArray1};
use pyo3::prelude::*;
use pyo3::types::PyDict;
use testrig::chain::{
    AdcChoice, AnalyserSetting, AnalyserWords, LowPassWords, analyse_analogue, anti_aliased,
};

use crate::errors::{TestrigError, to_py};

/// The averaged spectrum of `signal` sampled at `rate_hz`: through the low-pass `filter`
/// (`"butterworth"` or `"bessel"` of `filter_order` at `cutoff_hz`, default `fmax_hz`;
/// `None`: none), an ADC of `bits` over ±`range` (default: the signal's largest
/// magnitude), and the analyser (`block` points, `window`, `averages` linear averages,
/// `overlap_pct`, `sampling` "thesis" fs = 2 fmax or "2.56"). Returns a dict:
/// `frequency_hz`, `power` (the signal's unit squared, RMS), `alias_of_hz` (NaN where
/// the line is not an alias), `averages`, `adc_overloads`, `floor` (the ADC's
/// quantisation noise in one line).
#[pyfunction]
#[pyo3(signature = (signal, rate_hz, fmax_hz, block=1024, window="hanning", averages=10, overlap_pct=0.0, sampling="thesis", bits=12, range=None, filter=None, filter_order=8, cutoff_hz=None))]
#[allow(clippy::too_many_arguments)]
pub fn analyse<'py>(
    py: Python<'py>,
    signal: PyReadonlyArray1<'py, f64>,
    rate_hz: f64,
    fmax_hz: f64,
    block: usize,
    window: &str,
    averages: usize,
    overlap_pct: f64,
    sampling: &str,
    bits: u32,
    range: Option<f64>,
    filter: Option<&str>,
    filter_order: usize,
    cutoff_hz: Option<f64>,
) -> PyResult<Bound<'py, PyDict>> {
    let samples = signal.as_slice()?;
    if !(rate_hz.is_finite() && rate_hz > 0.0) {
        return Err(TestrigError::new_err(format!(
            "rate_hz {rate_hz}: a sample rate > 0 Hz"
        )));
    }
    let filter = LowPassWords {
        kind: filter_kind(filter)?,
        order: filter_order,
        cutoff_hz,
    };
    let spec = filter
        .spec(fmax_hz, rate_hz)
        .map_err(|e| TestrigError::new_err(format!("cutoff_hz: {e}")))?;
    let range_v = range.unwrap_or_else(|| {
        let peak = samples.iter().fold(0.0f64, |m, x| m.max(x.abs()));
        if peak > 0.0 { peak } else { 1.0 }
    });
    let words = AnalyserWords {
        fmax_hz,
        block,
        window: parse_window(window)?,
        averages,
        overlap: overlap_pct / 100.0,
        sampling: parse_sampling(sampling)?,
        adc: AdcChoice {
            bits,
            range_v,
            dither_seed: None,
        },
    };
    let spectrum = py.detach(|| -> anyhow::Result<_> {
        let setup = words.set_up(rate_hz).map_err(|e| {
            let name = match e.setting() {
                AnalyserSetting::Block => format!("block {block}"),
                AnalyserSetting::FmaxHz => format!("fmax_hz {fmax_hz}"),
                AnalyserSetting::Averages => format!("averages {averages}"),
                AnalyserSetting::OverlapPct => format!("overlap_pct {overlap_pct}"),
                AnalyserSetting::Adc => format!("bits {bits} / range {range_v}"),
            };
            anyhow::anyhow!("{name}: {e}")
        })?;
        let analogue = anti_aliased(samples, rate_hz, spec)?;
        analyse_analogue(setup, &analogue).ok_or_else(|| {
            anyhow::anyhow!(
                "signal: {} samples at {rate_hz} Hz are fewer than one block of {block} ADC samples",
                samples.len()
            )
        })
    });
    let spectrum = spectrum.map_err(to_py)?;
    let out = PyDict::new(py);
    let (frequency, power): (Vec<f64>, Vec<f64>) = spectrum
        .lines
        .iter()
        .map(|l| (l.frequency_hz, l.value))
        .unzip();
    let alias: Vec<f64> = spectrum
        .alias_of
        .iter()
        .map(|a| a.unwrap_or(f64::NAN))
        .collect();
    out.set_item("frequency_hz", frequency.into_pyarray(py))?;
    out.set_item("power", power.into_pyarray(py))?;
    out.set_item("alias_of_hz", alias.into_pyarray(py))?;
    out.set_item("averages", spectrum.averages)?;
    out.set_item("adc_overloads", spectrum.adc_overloads)?;
    out.set_item("floor", spectrum.floor)?;
    Ok(out)
}

/// The window named `window`.
fn parse_window(window: &str) -> PyResult<Window> {
    Window::parse(window).ok_or_else(|| {
        TestrigError::new_err(format!("window `{window}`: one of {}", Window::NAMES))
    })
}

/// The sampling named `sampling`: "thesis" (fs = 2 fmax) or "2.56".
fn parse_sampling(sampling: &str) -> PyResult<Sampling> {
    match sampling {
        "thesis" => Ok(Sampling::Thesis),
        "2.56" | "modern" => Ok(Sampling::Modern),
        other => Err(TestrigError::new_err(format!(
            "sampling `{other}`: \"thesis\" or \"2.56\""
        ))),
    }
}

/// The filter family named `filter` (`None` or "none": no filter).
fn filter_kind(filter: Option<&str>) -> PyResult<Option<FilterKind>> {
    match filter {
        None | Some("none") => Ok(None),
        Some("butterworth") => Ok(Some(FilterKind::Butterworth)),
        Some("bessel") => Ok(Some(FilterKind::Bessel)),
        Some(other) => Err(TestrigError::new_err(format!(
            "filter `{other}`: \"butterworth\", \"bessel\" or None"
        ))),
    }
}
