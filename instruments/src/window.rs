//! Analysis windows in their periodic (DFT-even) form, as a Fourier analyser applies them.

/// A window shape.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Window {
    /// Rectangular: no taper (best for transients and bin-centred lines).
    Uniform,
    /// Hann ("Hanning" on the HP 5451C): 0.5 − 0.5 cos(2πk/N).
    Hanning,
    /// Five-term flat-top (the HP/Matlab `flattop` coefficients): amplitude exact to
    /// within about 0.01 dB anywhere between bins.
    FlatTop,
}

/// Coefficients a0..a4 of the flat-top window Σ (−1)^m a_m cos(2πmk/N).
const FLAT_TOP: [f64; 5] = [
    0.215_578_95,
    0.416_631_58,
    0.277_263_158,
    0.083_578_947,
    0.006_947_368,
];

impl Window {
    /// Every name `parse` accepts.
    pub const NAMES: &'static str = "uniform, hanning, flattop";

    /// Parses `uniform`, `hanning` (or `hann`) or `flattop`.
    pub fn parse(text: &str) -> Option<Self> {
        match text {
            "uniform" | "rectangular" => Some(Self::Uniform),
            "hanning" | "hann" => Some(Self::Hanning),
            "flattop" | "flat-top" => Some(Self::FlatTop),
            _ => None,
        }
    }

    /// The name `parse` accepts.
    pub fn name(self) -> &'static str {
        match self {
            Self::Uniform => "uniform",
            Self::Hanning => "hanning",
            Self::FlatTop => "flattop",
        }
    }

    /// The N window values w[0..N].
    pub fn coefficients(self, n: usize) -> Vec<f64> {
        let cosine_sum = |a: &[f64]| -> Vec<f64> {
            (0..n)
                .map(|k| {
                    let x = std::f64::consts::TAU * k as f64 / n as f64;
                    a.iter()
                        .enumerate()
                        .map(|(m, &am)| if m % 2 == 0 { am } else { -am } * (m as f64 * x).cos())
                        .sum()
                })
                .collect()
        };
        match self {
            Self::Uniform => vec![1.0; n],
            Self::Hanning => cosine_sum(&[0.5, 0.5]),
            Self::FlatTop => cosine_sum(&FLAT_TOP),
        }
    }
}
