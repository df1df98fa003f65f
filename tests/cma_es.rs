//! The CMA-ES optimiser on standard test functions (Hansen's tutorial; the BBOB suite's
//! sphere, Rosenbrock and Rastrigin), mapped onto the unit box it searches.

use testrig::calibrate::{CmaEs, CmaSettings};

/// Minimises `f` from `start` until `target` or `budget` evaluations; returns the best
/// objective, the evaluations used, the best point and the restarts begun.
fn minimise(
    f: impl Fn(&[f64]) -> f64,
    start: Vec<f64>,
    seed: u64,
    budget: usize,
    target: f64,
) -> (f64, usize, Vec<f64>, usize) {
    let mut cma = CmaEs::new(CmaSettings {
        tol_x: 1e-12,
        ..CmaSettings::new(start, seed)
    });
    let mut used = 0;
    while used < budget {
        let candidates = cma.ask();
        let values: Vec<f64> = candidates.iter().map(|c| f(&c.x)).collect();
        used += values.len();
        cma.tell(&values);
        if cma.best().is_some_and(|(_, v)| v <= target) {
            break;
        }
    }
    let (x, v) = cma.best().expect("evaluated");
    eprintln!("best {v:e} after {used} evaluations");
    (v, used, x.to_vec(), cma.sigma_and_restart().1)
}

fn sphere(x: &[f64]) -> f64 {
    x.iter().map(|v| (v - 0.3).powi(2)).sum()
}

/// Rosenbrock on [−2, 2]ⁿ: minimum 0 at y = 1 (x = 0.75).
fn rosenbrock(x: &[f64]) -> f64 {
    let y: Vec<f64> = x.iter().map(|v| 4.0 * v - 2.0).collect();
    y.windows(2)
        .map(|w| 100.0 * (w[1] - w[0] * w[0]).powi(2) + (1.0 - w[0]).powi(2))
        .sum()
}

/// Rastrigin on [−5.12, 5.12]ⁿ: minimum 0 at y = 0 (x = 0.5), a local minimum at every
/// integer point.
fn rastrigin(x: &[f64]) -> f64 {
    let y: Vec<f64> = x.iter().map(|v| 10.24 * v - 5.12).collect();
    10.0 * y.len() as f64
        + y.iter()
            .map(|v| v * v - 10.0 * (std::f64::consts::TAU * v).cos())
            .sum::<f64>()
}

#[test]
fn the_sphere_is_solved_to_1e_10_within_2000_evaluations() {
    let (best, used, x, _) = minimise(sphere, vec![0.9; 8], 1, 2000, 1e-10);
    assert!(best <= 1e-10, "best {best} after {used}");
    assert!(x.iter().all(|v| (v - 0.3).abs() < 1e-4), "{x:?}");
}

#[test]
fn rosenbrock_in_5_d_reaches_its_valley_floor() {
    // Hansen's tutorial: about 10³–10⁴ evaluations in 5-D; the curved valley needs the
    // covariance to adapt (a fixed isotropic search stalls far from the minimum).
    let (best, used, x, _) = minimise(rosenbrock, vec![0.2; 5], 2, 20_000, 1e-8);
    assert!(best <= 1e-8, "best {best} after {used}");
    assert!(x.iter().all(|v| (v - 0.75).abs() < 1e-3), "{x:?}");
}

#[test]
fn restarts_find_rastrigins_global_minimum() {
    // In 3-D the first runs mostly end in a local minimum; IPOP restarts (doubling the
    // population) reach the global one.
    let (best, used, _, restarts) = minimise(rastrigin, vec![0.1; 3], 3, 60_000, 1e-8);
    assert!(best <= 1e-8, "best {best} after {used}");
    assert!(
        restarts >= 1,
        "solved without a restart: the test shows nothing about them"
    );
}

#[test]
fn an_optimum_on_the_boundary_is_reached_from_inside() {
    let f = |x: &[f64]| x[0] + (x[1] - 0.5).powi(2);
    let (best, _, x, _) = minimise(f, vec![0.8, 0.8], 4, 3000, 1e-9);
    assert!(best <= 1e-6, "{best}");
    assert!(x.iter().all(|v| (0.0..=1.0).contains(v)));
}

#[test]
fn the_same_seed_gives_the_same_search_and_another_seed_another() {
    let run = |seed| minimise(rosenbrock, vec![0.2; 3], seed, 300, 0.0);
    assert_eq!(run(7), run(7));
    assert_ne!(run(7).2, run(8).2);
}
