//! The spread of once-per-revolution samples taken every k revolutions.

/// RMS scatter of `samples` (one per revolution) about their k phase means, over k
/// interleaved subsequences (samples j, j + k, j + 2k, … for j = 0..k), in the samples'
/// unit. A motion that repeats every k revolutions has spread 0 for that k (and its
/// multiples). `None` when some phase has fewer than two samples.
pub fn section_spread(samples: &[f64], k: usize) -> Option<f64> {
    if k == 0 || samples.len() < 2 * k {
        return None;
    }
    let mut sum_sq = 0.0;
    let mut count = 0usize;
    for phase in 0..k {
        let values: Vec<f64> = samples.iter().skip(phase).step_by(k).copied().collect();
        let mean = values.iter().sum::<f64>() / values.len() as f64;
        sum_sq += values.iter().map(|v| (v - mean).powi(2)).sum::<f64>();
        count += values.len();
    }
    Some((sum_sq / count as f64).sqrt())
}

#[cfg(test)]
mod tests {
    use super::section_spread;

    #[test]
    fn a_period_two_sequence_scatters_every_revolution_but_not_every_two() {
        let samples: Vec<f64> = (0..40)
            .map(|n| if n % 2 == 0 { 1.0 } else { -1.0 })
            .collect();
        assert!((section_spread(&samples, 1).unwrap() - 1.0).abs() < 1e-12);
        assert!(section_spread(&samples, 2).unwrap() < 1e-12);
        assert!(section_spread(&samples, 4).unwrap() < 1e-12);
        assert!(section_spread(&samples, 3).unwrap() > 0.5);
        assert_eq!(section_spread(&samples[..3], 2), None);
    }
}
