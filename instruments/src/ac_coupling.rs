//! AC coupling: the input capacitor of an AC voltmeter or of a scope's AC input, a
//! first-order high-pass y[n] = a·(y[n−1] + x[n] − x[n−1]), a = e^(−2π f_c / f_s).

use num_complex::Complex64;

use crate::block::Block;
use crate::error::InstrumentError;

/// A first-order high-pass.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct AcCoupling {
    a: f64,
    previous_in: Option<f64>,
    previous_out: f64,
    rate_hz: f64,
}

impl AcCoupling {
    /// Corner `corner_hz` on a stream at `rate_hz`; the corner lies in (0, Nyquist).
    pub fn new(corner_hz: f64, rate_hz: f64) -> Result<Self, InstrumentError> {
        if !(rate_hz.is_finite()
            && corner_hz.is_finite()
            && corner_hz > 0.0
            && corner_hz < rate_hz / 2.0)
        {
            return Err(InstrumentError::setting(
                "AC coupling",
                "corner",
                corner_hz,
                "must lie between 0 and the stream's Nyquist frequency",
            ));
        }
        Ok(Self {
            a: (-std::f64::consts::TAU * corner_hz / rate_hz).exp(),
            previous_in: None,
            previous_out: 0.0,
            rate_hz,
        })
    }

    /// One sample through; the capacitor starts charged to the first input (the
    /// instrument is switched on to a steady signal).
    pub fn tick(&mut self, x: f64) -> f64 {
        let y = match self.previous_in {
            None => 0.0,
            Some(p) => self.a * (self.previous_out + x - p),
        };
        self.previous_in = Some(x);
        self.previous_out = y;
        y
    }
}

impl Block for AcCoupling {
    fn reset(&mut self) {
        self.previous_in = None;
        self.previous_out = 0.0;
    }

    fn process(&mut self, input: &[f64], output: &mut [f64]) {
        for (y, &x) in output.iter_mut().zip(input) {
            *y = self.tick(x);
        }
    }

    fn response(&self, freq_hz: f64) -> Option<Complex64> {
        let z = Complex64::from_polar(1.0, std::f64::consts::TAU * freq_hz / self.rate_hz);
        Some(self.a * (1.0 - 1.0 / z) / (1.0 - self.a / z))
    }
}
