//! The variable low-pass anti-alias filter (Barr & Stroud EF2 style): Butterworth or
//! Bessel of a chosen order and cut-off, as cascaded second-order sections, or bypassed.
//!
//! Design: the analog prototype's poles (−3 dB at 1 rad/s) are scaled to the pre-warped
//! cut-off Ω_c = 2 f_s tan(π f_c / f_s) and mapped by the bilinear transform
//! z = (1 + s/2f_s)/(1 − s/2f_s); the zeros at s = ∞ go to z = −1. Each section has unit
//! gain at DC. The −3 dB point of the digital filter is then exactly f_c.

use num_complex::Complex64;

use crate::analog::{bessel_poles, butterworth_poles};
use crate::biquad::Biquad;
use crate::block::Block;
use crate::error::{InstrumentError, require_positive};

/// Response family of the filter.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FilterKind {
    /// Maximally flat magnitude.
    Butterworth,
    /// Maximally flat group delay.
    Bessel,
}

/// Highest order offered.
pub const MAX_ORDER: usize = 12;

/// A low-pass setting.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LowPassSpec {
    /// Family.
    pub kind: FilterKind,
    /// Order (number of poles), 1..=12.
    pub order: usize,
    /// −3 dB frequency (Hz).
    pub cutoff_hz: f64,
}

/// The anti-alias filter block; `None` as spec means bypassed (output = input).
#[derive(Clone, Debug, PartialEq)]
pub struct AntiAliasFilter {
    spec: Option<LowPassSpec>,
    rate_hz: f64,
    sections: Vec<Biquad>,
}

impl AntiAliasFilter {
    /// Designs the filter for a stream at `rate_hz`; the cut-off must lie below the
    /// stream's Nyquist frequency.
    pub fn new(spec: Option<LowPassSpec>, rate_hz: f64) -> Result<Self, InstrumentError> {
        const NAME: &str = "anti-alias filter";
        require_positive(NAME, "sample rate", rate_hz)?;
        let sections = match spec {
            None => Vec::new(),
            Some(s) => {
                if !(1..=MAX_ORDER).contains(&s.order) {
                    return Err(InstrumentError::setting(
                        NAME,
                        "order",
                        s.order,
                        format!("must lie in 1..={MAX_ORDER}"),
                    ));
                }
                let nyquist = rate_hz / 2.0;
                if !(s.cutoff_hz.is_finite() && s.cutoff_hz > 0.0 && s.cutoff_hz < nyquist) {
                    return Err(InstrumentError::setting(
                        NAME,
                        "cut-off",
                        s.cutoff_hz,
                        format!(
                            "must lie in (0, {nyquist}) Hz, below the stream's Nyquist frequency"
                        ),
                    ));
                }
                design(s, rate_hz)
            }
        };
        Ok(Self {
            spec,
            rate_hz,
            sections,
        })
    }

    /// The setting, `None` when bypassed.
    pub fn spec(&self) -> Option<LowPassSpec> {
        self.spec
    }

    /// One sample through the filter.
    #[inline]
    pub fn tick(&mut self, x: f64) -> f64 {
        self.sections
            .iter_mut()
            .fold(x, |v, section| section.tick(v))
    }

    /// The second-order sections, in processing order.
    pub fn sections(&self) -> &[Biquad] {
        &self.sections
    }
}

/// Sections of the digital filter for `spec` at `rate_hz`.
fn design(spec: LowPassSpec, rate_hz: f64) -> Vec<Biquad> {
    let prototype = match spec.kind {
        FilterKind::Butterworth => butterworth_poles(spec.order),
        FilterKind::Bessel => bessel_poles(spec.order),
    };
    let warped = 2.0 * rate_hz * (std::f64::consts::PI * spec.cutoff_hz / rate_hz).tan();
    let to_z = |p: Complex64| {
        let s = p * warped / (2.0 * rate_hz);
        (1.0 + s) / (1.0 - s)
    };
    let mut sections = Vec::new();
    for p in prototype.iter().filter(|p| p.im > 1e-9) {
        let z = to_z(*p);
        let a = [-2.0 * z.re, z.norm_sqr()];
        let gain = (1.0 + a[0] + a[1]) / 4.0;
        sections.push(Biquad::new([gain, 2.0 * gain, gain], a));
    }
    for p in prototype.iter().filter(|p| p.im.abs() <= 1e-9) {
        let z = to_z(Complex64::new(p.re, 0.0)).re;
        let gain = (1.0 - z) / 2.0;
        sections.push(Biquad::new([gain, gain, 0.0], [-z, 0.0]));
    }
    sections
}

impl Block for AntiAliasFilter {
    fn reset(&mut self) {
        self.sections.iter_mut().for_each(Biquad::reset);
    }

    fn process(&mut self, input: &[f64], output: &mut [f64]) {
        for (y, &x) in output.iter_mut().zip(input) {
            *y = self
                .sections
                .iter_mut()
                .fold(x, |v, section| section.tick(v));
        }
    }

    fn response(&self, freq_hz: f64) -> Option<Complex64> {
        let omega = 2.0 * std::f64::consts::PI * freq_hz / self.rate_hz;
        Some(self.sections.iter().map(|s| s.response(omega)).product())
    }
}
