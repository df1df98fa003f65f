//! The anti-alias filter's one way in: its family, order and cut-off in a user's words
//! (the cut-off left out follows the analyser's band) become a checked low-pass on a
//! stream, or an error saying what a cut-off may be. The scenario reader, the panel's
//! filter command, `testrig analyse` and Python's `analyse` all come through here.

use instruments::{FilterKind, LowPassSpec};

/// A low-pass filter in a user's words, before any check.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LowPassWords {
    /// Family; `None` for no filter.
    pub kind: Option<FilterKind>,
    /// Order (poles).
    pub order: usize,
    /// Cut-off (Hz); `None`: the band it guards.
    pub cutoff_hz: Option<f64>,
}

/// Why a low-pass cannot run as asked.
#[derive(Debug, PartialEq, thiserror::Error)]
pub enum LowPassError {
    /// The cut-off is not in (0, Nyquist).
    #[error("{cutoff_hz} Hz{} lies outside (0, {nyquist_hz}) Hz: a cut-off lies above 0 and below the stream's Nyquist frequency (half its rate)", if *.defaulted { " (left out: the band's top)" } else { "" })]
    Cutoff {
        /// The cut-off in question (Hz).
        cutoff_hz: f64,
        /// Whether it was left out and taken from the band.
        defaulted: bool,
        /// Half the stream's rate (Hz).
        nyquist_hz: f64,
    },
}

impl LowPassWords {
    /// No filter.
    pub const NONE: Self = Self {
        kind: None,
        order: 0,
        cutoff_hz: None,
    };

    /// The filter's spec on a stream at `stream_hz`, its cut-off `band_hz` where left
    /// out; `None` for no filter.
    pub fn spec(&self, band_hz: f64, stream_hz: f64) -> Result<Option<LowPassSpec>, LowPassError> {
        let Some(kind) = self.kind else {
            return Ok(None);
        };
        let cutoff_hz = self.cutoff_hz.unwrap_or(band_hz);
        let nyquist_hz = stream_hz / 2.0;
        if !(cutoff_hz.is_finite() && cutoff_hz > 0.0 && cutoff_hz < nyquist_hz) {
            return Err(LowPassError::Cutoff {
                cutoff_hz,
                defaulted: self.cutoff_hz.is_none(),
                nyquist_hz,
            });
        }
        Ok(Some(LowPassSpec {
            kind,
            order: self.order,
            cutoff_hz,
        }))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_cut_off_left_out_follows_the_band_and_must_lie_below_nyquist() {
        let words = LowPassWords {
            kind: Some(FilterKind::Butterworth),
            order: 8,
            cutoff_hz: None,
        };
        let spec = words.spec(200.0, 51_200.0).expect("ok").expect("a filter");
        assert_eq!(spec.cutoff_hz, 200.0);
        assert!(matches!(
            words.spec(30_000.0, 51_200.0),
            Err(LowPassError::Cutoff {
                defaulted: true,
                ..
            })
        ));
        let zero = LowPassWords {
            cutoff_hz: Some(0.0),
            ..words
        };
        assert!(zero.spec(200.0, 51_200.0).is_err());
        assert_eq!(LowPassWords::NONE.spec(200.0, 51_200.0), Ok(None));
    }
}
