//! The 0-1 test for chaos (Gottwald & Melbourne, "On the implementation of the 0–1 test
//! for chaos", SIAM J. Appl. Dyn. Syst. 8, 2009, the correlation method): K near 0 for a
//! regular (periodic or quasi-periodic) sequence, near 1 for a chaotic one.

/// Frequencies c tried, spread over (π/5, 4π/5) as the paper advises (away from the
/// resonances at 0 and π); the median over them is K.
const FREQUENCIES: usize = 100;

/// K of the 0-1 test on `samples` (e.g. once per revolution), median over fixed c (no
/// random draw: the same samples give the same K). `None` below 40 samples, where the
/// mean-square displacement has too few lags to correlate.
pub fn zero_one_k(samples: &[f64]) -> Option<f64> {
    let n = samples.len();
    if n < 40 {
        return None;
    }
    let mean = samples.iter().sum::<f64>() / n as f64;
    let centred: Vec<f64> = samples.iter().map(|v| v - mean).collect();
    let scale = centred.iter().map(|v| v.abs()).fold(0.0, f64::max);
    if scale == 0.0 {
        return Some(0.0);
    }
    let mut ks: Vec<f64> = (0..FREQUENCIES)
        .map(|i| {
            // Golden-ratio offsets keep the c's from lining up with one another.
            let u = (i as f64 * 0.618_033_988_749_895).fract();
            let c = std::f64::consts::PI * (0.2 + 0.6 * u);
            k_at(&centred, c)
        })
        .collect();
    ks.sort_by(f64::total_cmp);
    Some(0.5 * (ks[FREQUENCIES / 2 - 1] + ks[FREQUENCIES / 2]))
}

/// K_c: the correlation of the mean-square displacement of the translation variables
/// (p, q) with the lag, for lags up to a tenth of the samples.
fn k_at(phi: &[f64], c: f64) -> f64 {
    let n = phi.len();
    let (mut p, mut q) = (Vec::with_capacity(n), Vec::with_capacity(n));
    let (mut ps, mut qs) = (0.0, 0.0);
    for (j, v) in phi.iter().enumerate() {
        let angle = (j + 1) as f64 * c;
        ps += v * angle.cos();
        qs += v * angle.sin();
        p.push(ps);
        q.push(qs);
    }
    let lags = n / 10;
    let msd = mean_square_displacement(&p, &q, lags);
    let xi: Vec<f64> = (1..=lags).map(|l| l as f64).collect();
    correlation(&xi, &msd)
}

/// Lags summed side by side in [`mean_square_displacement`].
const LANES: usize = 4;

/// M(lag) = mean over j of (p[j + lag] − p[j])² + (q[j + lag] − q[j])², for lags 1 to
/// `lags`. [`LANES`] lags are summed side by side, each in its own chain in the order of
/// j (the same sums, bit for bit, as one lag at a time): one chain's additions wait on
/// one another, so a lag at a time ran at a quarter of the adder's pace.
fn mean_square_displacement(p: &[f64], q: &[f64], lags: usize) -> Vec<f64> {
    let n = p.len();
    let lag_sum = |lag: usize, from: usize, sum: f64| {
        p[from + lag..]
            .iter()
            .zip(&p[from..n - lag])
            .zip(q[from + lag..].iter().zip(&q[from..n - lag]))
            .fold(sum, |s, ((a, b), (c, d))| {
                s + ((a - b).powi(2) + (c - d).powi(2))
            })
    };
    let mut msd = Vec::with_capacity(lags);
    let mut first = 1;
    // Groups of LANES lags: the terms all of them have side by side, then each lag's own.
    while first + LANES - 1 <= lags {
        let shared = n - (first + LANES - 1);
        let (p0, q0) = (&p[..shared], &q[..shared]);
        let ps: [&[f64]; LANES] = std::array::from_fn(|k| &p[first + k..first + k + shared]);
        let qs: [&[f64]; LANES] = std::array::from_fn(|k| &q[first + k..first + k + shared]);
        let mut sums = [0.0; LANES];
        for j in 0..shared {
            for k in 0..LANES {
                sums[k] += (ps[k][j] - p0[j]).powi(2) + (qs[k][j] - q0[j]).powi(2);
            }
        }
        for (k, sum) in sums.into_iter().enumerate() {
            let lag = first + k;
            msd.push(lag_sum(lag, shared, sum) / (n - lag) as f64);
        }
        first += LANES;
    }
    for lag in first..=lags {
        msd.push(lag_sum(lag, 0, 0.0) / (n - lag) as f64);
    }
    msd
}

/// Pearson correlation; 0 when either sequence is constant.
fn correlation(a: &[f64], b: &[f64]) -> f64 {
    let n = a.len() as f64;
    let (ma, mb) = (a.iter().sum::<f64>() / n, b.iter().sum::<f64>() / n);
    let (mut sab, mut saa, mut sbb) = (0.0, 0.0, 0.0);
    for (x, y) in a.iter().zip(b) {
        sab += (x - ma) * (y - mb);
        saa += (x - ma).powi(2);
        sbb += (y - mb).powi(2);
    }
    if saa == 0.0 || sbb == 0.0 {
        return 0.0;
    }
    sab / (saa * sbb).sqrt()
}

#[cfg(test)]
mod tests {
    use super::{mean_square_displacement, zero_one_k};

    #[test]
    fn lags_summed_side_by_side_give_each_lag_s_own_sum_bit_for_bit() {
        for n in [40, 41, 97, 650] {
            let p: Vec<f64> = (0..n).map(|j| (j as f64 * 0.37).sin() * 1e3).collect();
            let q: Vec<f64> = (0..n).map(|j| (j as f64 * 0.11).cos() / 7.0).collect();
            for lags in [1, 3, 4, 5, n / 10, n / 2] {
                let together = mean_square_displacement(&p, &q, lags);
                assert_eq!(together.len(), lags);
                for (lag, &m) in (1..=lags).zip(&together) {
                    let alone = (0..n - lag)
                        .map(|j| (p[j + lag] - p[j]).powi(2) + (q[j + lag] - q[j]).powi(2))
                        .sum::<f64>()
                        / (n - lag) as f64;
                    assert_eq!(m.to_bits(), alone.to_bits(), "n {n}, lag {lag} of {lags}");
                }
            }
        }
    }

    #[test]
    fn the_logistic_map_at_r_4_is_chaotic_and_at_r_3_2_is_not() {
        let logistic = |r: f64| -> Vec<f64> {
            let mut x = 0.3;
            (0..1200)
                .map(|_| {
                    x = r * x * (1.0 - x);
                    x
                })
                .skip(200)
                .collect()
        };
        let chaotic = zero_one_k(&logistic(4.0)).unwrap();
        let period_two = zero_one_k(&logistic(3.2)).unwrap();
        assert!(chaotic > 0.9, "r = 4: K = {chaotic}");
        assert!(period_two < 0.1, "r = 3.2: K = {period_two}");
    }

    #[test]
    fn a_quasi_periodic_sequence_is_regular() {
        let samples: Vec<f64> = (0..1000)
            .map(|n| (n as f64 * 2.0_f64.sqrt()).sin() + 0.5 * (n as f64 * 0.3).cos())
            .collect();
        let k = zero_one_k(&samples).unwrap();
        assert!(k < 0.2, "K = {k}");
    }
}
