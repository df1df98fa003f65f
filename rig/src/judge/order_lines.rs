//! The spectrum of a settled signal seen in orders of the running speed: how much of its
//! power sits on the lines of period k (multiples of the running speed / k), and how far a
//! subharmonic line stands over the broadband floor around it.

use std::cell::RefCell;
use std::sync::Arc;

use rustfft::num_complex::Complex;
use rustfft::{Fft, FftPlanner};

/// Bins each side of a line counted as the line: the Hann window's main lobe (±2 bins).
const LINE_HALF_WIDTH: usize = 2;
/// Lines of one family closer than this many bins are not told apart from broadband.
const MIN_LINE_SPACING_BINS: f64 = 10.0;
/// Heights are capped here (dB): a floor this far down is rounding, not broadband motion.
pub const MAX_HEIGHT_DB: f64 = 150.0;
/// Lowest bins left out as the mean's leakage.
const DC_BINS: usize = LINE_HALF_WIDTH + 1;

/// The one-sided power spectrum (Hann window, mean removed) of a signal taken at a fixed
/// running speed, in bins of `1 / T` Hz.
#[derive(Clone, Debug)]
pub struct OrderSpectrum {
    power: Vec<f64>,
    bin_hz: f64,
    running_hz: f64,
    band_bins: usize,
}

impl OrderSpectrum {
    /// The spectrum of `signal` sampled at `rate_hz`, with the gear turning at
    /// `running_hz` (rev/s); the band reaches `band_orders` times the running speed (or
    /// 0.9 of Nyquist, whichever is lower).
    pub fn new(signal: &[f64], rate_hz: f64, running_hz: f64, band_orders: f64) -> Self {
        let n = signal.len();
        let mean = signal.iter().sum::<f64>() / n.max(1) as f64;
        let mut data: Vec<Complex<f64>> = Vec::with_capacity(n);
        if n > 0 {
            let (fft, hann) = plan_of(n);
            data.extend(
                signal
                    .iter()
                    .zip(hann.iter())
                    .map(|(v, w)| Complex::new((v - mean) * w, 0.0)),
            );
            fft.process(&mut data);
        }
        let bin_hz = rate_hz / n.max(1) as f64;
        let top_hz = (band_orders * running_hz).min(0.45 * rate_hz);
        let band_bins = ((top_hz / bin_hz) as usize).min(n / 2);
        let power = data[..=band_bins.min(data.len().saturating_sub(1))]
            .iter()
            .map(|c| c.norm_sqr())
            .collect();
        Self {
            power,
            bin_hz,
            running_hz,
            band_bins,
        }
    }

    /// Share of the band's power (above the mean's leakage) that lies on the lines at
    /// multiples of running speed / k; `None` when those lines are too close to resolve.
    pub fn line_fraction(&self, k: usize) -> Option<f64> {
        let mask = self.family_mask(k, LINE_HALF_WIDTH)?;
        let (mut on, mut all) = (0.0, 0.0);
        for (i, p) in self.power.iter().enumerate().skip(DC_BINS) {
            all += p;
            if mask[i] {
                on += p;
            }
        }
        Some(if all > 0.0 { on / all } else { 1.0 })
    }

    /// Power of the line at `order` (within the main lobe) over the broadband floor around
    /// it (dB): the floor is the median bin over half an order each side, the lines of
    /// period `k` (multiples of running speed / k) and their skirts left out, times the
    /// line's width in bins. `None` when the line lies beyond the band or unresolved.
    pub fn height_over_floor_db(&self, order: f64, k: usize) -> Option<f64> {
        let centre = (order * self.running_hz / self.bin_hz).round() as usize;
        let half_order_bins = (0.5 * self.running_hz / self.bin_hz) as usize;
        if centre < DC_BINS || centre + half_order_bins > self.band_bins {
            return None;
        }
        let line: f64 = self.power[centre - LINE_HALF_WIDTH..=centre + LINE_HALF_WIDTH]
            .iter()
            .sum();
        let mask = self.family_mask(k, LINE_HALF_WIDTH + 1)?;
        let mut floor: Vec<f64> = (centre.saturating_sub(half_order_bins)
            ..=centre + half_order_bins)
            .filter(|&i| i >= DC_BINS && !mask[i])
            .map(|i| self.power[i])
            .collect();
        if floor.is_empty() {
            return None;
        }
        floor.sort_by(f64::total_cmp);
        let median = floor[floor.len() / 2];
        if line <= 0.0 {
            return None;
        }
        let width = (2 * LINE_HALF_WIDTH + 1) as f64;
        let floor_power = (median * width).max(line * 10f64.powf(-MAX_HEIGHT_DB / 10.0));
        Some(10.0 * (line / floor_power).log10())
    }

    /// Share of the band's power (above the mean's leakage) within the main lobe of the
    /// line at `order`; `None` when the line lies beyond the band or in the mean's
    /// leakage.
    pub fn line_share(&self, order: f64) -> Option<f64> {
        let centre = (order * self.running_hz / self.bin_hz).round() as usize;
        if centre < DC_BINS + LINE_HALF_WIDTH || centre + LINE_HALF_WIDTH > self.band_bins {
            return None;
        }
        let all: f64 = self.power.iter().skip(DC_BINS).sum();
        let line: f64 = self.power[centre - LINE_HALF_WIDTH..=centre + LINE_HALF_WIDTH]
            .iter()
            .sum();
        Some(if all > 0.0 { line / all } else { 0.0 })
    }

    /// The bins within `half_width` of a line at a multiple of running speed / k.
    fn family_mask(&self, k: usize, half_width: usize) -> Option<Vec<bool>> {
        let spacing = self.running_hz / k as f64 / self.bin_hz;
        if k == 0 || spacing < MIN_LINE_SPACING_BINS {
            return None;
        }
        let mut mask = vec![false; self.power.len()];
        let mut m = 1.0;
        while m * spacing <= self.band_bins as f64 + half_width as f64 {
            let centre = (m * spacing).round() as usize;
            for i in centre.saturating_sub(half_width)..=centre + half_width {
                if let Some(b) = mask.get_mut(i) {
                    *b = true;
                }
            }
            m += 1.0;
        }
        Some(mask)
    }
}

/// A forward transform of some length and the Hann window of that length.
type Plan = (Arc<dyn Fft<f64>>, Arc<[f64]>);

thread_local! {
    /// The last length's forward transform and Hann window, kept for the thread: a
    /// campaign judges many windows of one length, and planning one (its twiddles' sines
    /// and cosines) and the window's cosines cost more than the transform. One length
    /// only, so that a thread judging windows of many lengths holds one plan.
    static LAST_PLAN: RefCell<Option<Plan>> = const { RefCell::new(None) };
}

/// The forward transform of length `n` and the periodic Hann window
/// w_i = ½ − ½ cos(2πi/n).
fn plan_of(n: usize) -> Plan {
    LAST_PLAN.with(|last| {
        let mut last = last.borrow_mut();
        if let Some((fft, hann)) = last.as_ref()
            && hann.len() == n
        {
            return (Arc::clone(fft), Arc::clone(hann));
        }
        let fft = FftPlanner::new().plan_fft_forward(n);
        let hann: Arc<[f64]> = (0..n)
            .map(|i| 0.5 - 0.5 * (2.0 * std::f64::consts::PI * i as f64 / n as f64).cos())
            .collect();
        *last = Some((Arc::clone(&fft), Arc::clone(&hann)));
        (fft, hann)
    })
}

/// Height (dB) of the 1/k-order line of `spectrum` over its floor, the floor taken
/// between the lines of period k.
pub fn subharmonic_height_db(spectrum: &OrderSpectrum, k: usize) -> Option<f64> {
    spectrum.height_over_floor_db(1.0 / k as f64, k)
}

/// Share of the band's power on the 1/k-order line of `spectrum`.
pub fn subharmonic_share(spectrum: &OrderSpectrum, k: usize) -> Option<f64> {
    spectrum.line_share(1.0 / k as f64)
}
