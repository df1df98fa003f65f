//! CMA-ES, the covariance matrix adaptation evolution strategy (Hansen, "The CMA Evolution
//! Strategy: A Tutorial", arXiv:1604.00772, 2016; the (μ/μ_w, λ) form with rank-one and
//! rank-μ updates and cumulative step-size adaptation), on the unit box [0, 1]ⁿ, with
//! IPOP restarts (Auger and Hansen, CEC 2005: each restart doubles the population).
//!
//! The search is driven from outside: [`CmaEs::ask`] gives a generation's candidates,
//! [`CmaEs::tell`] takes their objectives. So the caller evaluates in parallel, logs every
//! evaluation and, given the same seed and the same objectives, replays a search exactly.

use instruments::GaussianSource;
use nalgebra::{DMatrix, DVector, SymmetricEigen};

/// Settings of a search.
#[derive(Clone, Debug, PartialEq)]
pub struct CmaSettings {
    /// Start of the first run's mean, in the unit box.
    pub start: Vec<f64>,
    /// Initial step size, as a fraction of the box's side.
    pub sigma0: f64,
    /// Population of the first run (`None`: 4 + ⌊3 ln n⌋).
    pub population: Option<usize>,
    /// Seed of the sampling.
    pub seed: u64,
    /// A run ends when σ·√max(C_ii) falls below this (box fraction).
    pub tol_x: f64,
    /// A run ends when the best objective has not improved by more than this ...
    pub tol_fun: f64,
    /// ... over this many generations.
    pub stall_generations: usize,
}

impl CmaSettings {
    /// Dimension: the number of free parameters.
    pub fn dim(&self) -> usize {
        self.start.len()
    }

    /// Defaults for `dim` parameters starting at `start`.
    pub fn new(start: Vec<f64>, seed: u64) -> Self {
        let dim = start.len();
        Self {
            start,
            sigma0: 0.3,
            population: None,
            seed,
            tol_x: 1e-4,
            tol_fun: 1e-9,
            stall_generations: 10 + (30 * dim).div_ceil(4 + dim),
        }
    }
}

/// One candidate of a generation.
#[derive(Clone, Debug, PartialEq)]
pub struct Candidate {
    /// Position in the unit box (after mirroring into it).
    pub x: Vec<f64>,
    /// Restart it belongs to (0 is the first run).
    pub restart: usize,
    /// Generation within the restart.
    pub generation: usize,
}

/// The strategy's state.
pub struct CmaEs {
    settings: CmaSettings,
    normals: GaussianSource,
    run: Run,
    restart: usize,
    best: Option<(Vec<f64>, f64)>,
}

/// One run (between restarts).
struct Run {
    lambda: usize,
    mu: usize,
    weights: Vec<f64>,
    mu_eff: f64,
    c_c: f64,
    c_s: f64,
    c_1: f64,
    c_mu: f64,
    d_s: f64,
    chi_n: f64,
    mean: DVector<f64>,
    sigma: f64,
    cov: DMatrix<f64>,
    basis: DMatrix<f64>,
    scales: DVector<f64>,
    p_s: DVector<f64>,
    p_c: DVector<f64>,
    generation: usize,
    history: Vec<f64>,
    pending: Vec<DVector<f64>>,
}

impl Run {
    fn new(settings: &CmaSettings, lambda: usize, mean: Vec<f64>) -> Self {
        let n = settings.dim() as f64;
        let mu = lambda / 2;
        let raw: Vec<f64> = (0..mu)
            .map(|i| (mu as f64 + 0.5).ln() - ((i + 1) as f64).ln())
            .collect();
        let total: f64 = raw.iter().sum();
        let weights: Vec<f64> = raw.iter().map(|w| w / total).collect();
        let mu_eff = 1.0 / weights.iter().map(|w| w * w).sum::<f64>();
        let c_c = (4.0 + mu_eff / n) / (n + 4.0 + 2.0 * mu_eff / n);
        let c_s = (mu_eff + 2.0) / (n + mu_eff + 5.0);
        let c_1 = 2.0 / ((n + 1.3).powi(2) + mu_eff);
        let c_mu =
            (1.0 - c_1).min(2.0 * (mu_eff - 2.0 + 1.0 / mu_eff) / ((n + 2.0).powi(2) + mu_eff));
        let d_s = 1.0 + 2.0 * (((mu_eff - 1.0) / (n + 1.0)).sqrt() - 1.0).max(0.0) + c_s;
        let chi_n = n.sqrt() * (1.0 - 1.0 / (4.0 * n) + 1.0 / (21.0 * n * n));
        let dim = settings.dim();
        Self {
            lambda,
            mu,
            weights,
            mu_eff,
            c_c,
            c_s,
            c_1,
            c_mu,
            d_s,
            chi_n,
            mean: DVector::from_vec(mean),
            sigma: settings.sigma0,
            cov: DMatrix::identity(dim, dim),
            basis: DMatrix::identity(dim, dim),
            scales: DVector::from_element(dim, 1.0),
            p_s: DVector::zeros(dim),
            p_c: DVector::zeros(dim),
            generation: 0,
            history: Vec::new(),
            pending: Vec::new(),
        }
    }
}

impl CmaEs {
    /// A search with `settings`.
    pub fn new(settings: CmaSettings) -> Self {
        let n = settings.dim().max(1) as f64;
        let lambda = settings
            .population
            .unwrap_or(4 + (3.0 * n.ln()).floor() as usize)
            .max(4);
        let start = settings.start.iter().map(|v| v.clamp(0.0, 1.0)).collect();
        let run = Run::new(&settings, lambda, start);
        Self {
            normals: GaussianSource::new(settings.seed),
            settings,
            run,
            restart: 0,
            best: None,
        }
    }

    /// The next generation's candidates (λ of them), in the unit box.
    pub fn ask(&mut self) -> Vec<Candidate> {
        let run_index = self.restart;
        let generation = self.run.generation;
        let mut out = Vec::with_capacity(self.run.lambda);
        self.run.pending.clear();
        for _ in 0..self.run.lambda {
            let z = DVector::from_fn(self.settings.dim(), |_, _| self.normals.sample());
            let y = &self.run.basis * self.run.scales.component_mul(&z);
            let x = (&self.run.mean + y * self.run.sigma).map(mirror_into_unit);
            out.push(Candidate {
                x: x.iter().copied().collect(),
                restart: run_index,
                generation,
            });
            self.run.pending.push(x);
        }
        out
    }

    /// Takes the objectives (lower is better) of the candidates of the last [`ask`], in
    /// order, and updates the distribution; restarts with a doubled population when the
    /// run has converged or stalled. Returns whether a restart began.
    ///
    /// [`ask`]: CmaEs::ask
    pub fn tell(&mut self, objectives: &[f64]) -> bool {
        let pending = std::mem::take(&mut self.run.pending);
        let mut order: Vec<usize> = (0..pending.len().min(objectives.len())).collect();
        order.sort_by(|&a, &b| objectives[a].total_cmp(&objectives[b]));
        if let Some(&i) = order.first()
            && self.best.as_ref().is_none_or(|(_, f)| objectives[i] < *f)
        {
            self.best = Some((pending[i].iter().copied().collect(), objectives[i]));
        }
        self.update(&pending, &order);
        self.run
            .history
            .push(order.first().map_or(f64::INFINITY, |&i| objectives[i]));
        if self.converged() {
            self.restart += 1;
            let lambda = self.run.lambda * 2;
            // A fresh start anywhere in the box, most likely its middle half.
            let start: Vec<f64> = (0..self.settings.dim())
                .map(|_| mirror_into_unit(0.5 + 0.25 * self.normals.sample()))
                .collect();
            self.run = Run::new(&self.settings, lambda, start);
            return true;
        }
        false
    }

    /// The best candidate told so far and its objective.
    pub fn best(&self) -> Option<(&[f64], f64)> {
        self.best.as_ref().map(|(x, f)| (x.as_slice(), *f))
    }

    /// Current step size (box fraction) and restart index.
    pub fn sigma_and_restart(&self) -> (f64, usize) {
        (self.run.sigma, self.restart)
    }

    fn update(&mut self, pending: &[DVector<f64>], order: &[usize]) {
        let r = &mut self.run;
        if order.len() < r.mu {
            return;
        }
        let n = self.settings.dim() as f64;
        let old_mean = r.mean.clone();
        let steps: Vec<DVector<f64>> = order[..r.mu]
            .iter()
            .map(|&i| (&pending[i] - &old_mean) / r.sigma)
            .collect();
        let y_w = steps
            .iter()
            .zip(&r.weights)
            .fold(DVector::zeros(self.settings.dim()), |acc, (y, w)| {
                acc + y * *w
            });
        r.mean = &old_mean + &y_w * r.sigma;
        let inv_sqrt = &r.basis
            * DMatrix::from_diagonal(&r.scales.map(|d| 1.0 / d.max(1e-300)))
            * r.basis.transpose();
        r.p_s =
            &r.p_s * (1.0 - r.c_s) + (&inv_sqrt * &y_w) * (r.c_s * (2.0 - r.c_s) * r.mu_eff).sqrt();
        let g = (r.generation + 1) as f64;
        let ps_norm = r.p_s.norm();
        let h_s = ps_norm / (1.0 - (1.0 - r.c_s).powf(2.0 * g)).sqrt()
            < (1.4 + 2.0 / (n + 1.0)) * r.chi_n;
        let h = if h_s { 1.0 } else { 0.0 };
        r.p_c = &r.p_c * (1.0 - r.c_c) + &y_w * (h * (r.c_c * (2.0 - r.c_c) * r.mu_eff).sqrt());
        let rank_mu = steps.iter().zip(&r.weights).fold(
            DMatrix::zeros(self.settings.dim(), self.settings.dim()),
            |acc, (y, w)| acc + y * y.transpose() * *w,
        );
        let decay = 1.0 - r.c_1 - r.c_mu + (1.0 - h) * r.c_1 * r.c_c * (2.0 - r.c_c);
        r.cov = &r.cov * decay + &r.p_c * r.p_c.transpose() * r.c_1 + rank_mu * r.c_mu;
        r.cov = (&r.cov + r.cov.transpose()) * 0.5;
        r.sigma *= ((r.c_s / r.d_s) * (ps_norm / r.chi_n - 1.0)).exp();
        r.sigma = r.sigma.min(1.0);
        let eigen = SymmetricEigen::new(r.cov.clone());
        r.scales = eigen.eigenvalues.map(|v| v.max(1e-20).sqrt());
        r.basis = eigen.eigenvectors;
        r.generation += 1;
    }

    /// Whether the run has converged (step below `tol_x`), stalled, or its distribution
    /// degenerated.
    fn converged(&self) -> bool {
        let r = &self.run;
        let spread = r.sigma * r.cov.diagonal().max().sqrt();
        let stalled = r.history.len() > self.settings.stall_generations && {
            let recent = &r.history[r.history.len() - self.settings.stall_generations..];
            let before = r.history[..r.history.len() - self.settings.stall_generations]
                .iter()
                .copied()
                .fold(f64::INFINITY, f64::min);
            let now = recent.iter().copied().fold(f64::INFINITY, f64::min);
            before - now <= self.settings.tol_fun
        };
        let condition = r.scales.max() / r.scales.min().max(1e-300);
        spread < self.settings.tol_x || stalled || !spread.is_finite() || condition > 1e7
    }
}

/// Folds a coordinate back into [0, 1] by mirroring at the walls (period 2).
fn mirror_into_unit(v: f64) -> f64 {
    if !v.is_finite() {
        return 0.5;
    }
    let m = v.rem_euclid(2.0);
    if m > 1.0 { 2.0 - m } else { m }
}
