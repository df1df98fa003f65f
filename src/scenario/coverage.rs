//! Whether each measurement of a plan fits its run: the analyser's averages and the
//! scope's sweep must end before the next measurement starts and before the run ends.
//! Checked before a run starts, so a user learns at once (or, with `--strict`, the run
//! is refused) instead of finding short or missing spectra afterwards.

use instruments::AnalyserSettings;

use super::run_plan::Plan;

/// Time (s) the analyser needs for its whole average: the first block and a hop
/// for each further one.
pub fn analyser_span_s(settings: &AnalyserSettings) -> f64 {
    let fs = settings.sample_rate_hz();
    (settings.block as f64 + (settings.averages.saturating_sub(1) * settings.hop()) as f64) / fs
}

/// Averages of `settings` that fit in `available_s` seconds.
fn averages_within(settings: &AnalyserSettings, available_s: f64) -> usize {
    let fs = settings.sample_rate_hz();
    let block_s = settings.block as f64 / fs;
    if available_s < block_s {
        return 0;
    }
    let hop_s = settings.hop() as f64 / fs;
    (1 + ((available_s - block_s) / hop_s + 1e-9).floor() as usize).min(settings.averages)
}

/// One warning per measurement of `plan` that cannot complete, saying what is lost.
pub fn measurement_warnings(plan: &Plan) -> Vec<String> {
    let measures = plan.measurements();
    let mut warnings = Vec::new();
    for (i, m) in measures.iter().enumerate() {
        let name = format!("measurement {} ({}) at {} s", i + 1, m.label, m.at_s);
        if m.at_s >= plan.duration_s {
            warnings.push(format!(
                "{name}: the run ends at {} s, before it; nothing is measured",
                plan.duration_s
            ));
            continue;
        }
        let (end_s, until) = match measures.get(i + 1) {
            Some(next) if next.at_s < plan.duration_s => (next.at_s, "the next measurement"),
            _ => (plan.duration_s, "the run's end"),
        };
        let available_s = end_s - m.at_s;
        if let Some(analyser) = &plan.analyser {
            let s = &analyser.settings;
            let need_s = analyser_span_s(s);
            if need_s > available_s + 1e-9 {
                warnings.push(format!(
                    "{name}: {} averages need {need_s:.3} s, {until} leaves {available_s:.3} s: {} of {} averages",
                    s.averages,
                    averages_within(s, available_s),
                    s.averages
                ));
            }
        }
        if let Some(scope) = &plan.chain.scope {
            let sweep_s = 10.0 * scope.settings.seconds_per_div;
            if sweep_s > available_s + 1e-9 {
                warnings.push(format!(
                    "{name}: the scope's sweep of {sweep_s} s does not fit in the {available_s:.3} s {until} leaves; no trace"
                ));
            }
        }
    }
    warnings
}
