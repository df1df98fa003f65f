//! `report.md`: a sweep of the 1983 rig (a preset, or a rig file that reproduces it) held
//! against the thesis's findings (Basmaji 1983, ch. IV), point by point and scored, its
//! healthy cases only (the thesis saw no faults); another rig's, what its points held. A
//! rig file's sweep then lists each case (`case_table.rs`), and every report ends with
//! the plots. A finding the grid has no points for is reported as not covered, never as
//! reproduced or not.

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

use super::case_result::CaseResult;
use super::case_table::{each_case, rig_summary};
use super::facts::facts;
use super::meta::SweepMeta;
use super::motion_lines::motion_lines;
use super::sequence::Direction;
use super::thesis::{
    HALF_ORDER_FROM_RPM, HEAVY_LOAD_NM, MEASURED_FUNDAMENTAL_HZ, MEASURED_RESONANCE_RPM,
    PERIOD_ONE_BELOW_RPM, RESONANCE_MIN_SPEEDS, RESONANCE_TOLERANCE, VANISHES_FROM_RPM, lab_score,
    physics_match, physics_score, score, thesis_expects_half_order, thesis_motion,
};
use crate::recording::PartialFile;

/// The share of decided points (%) the thesis asks a preset to match, for both scores.
const TARGET_PERCENT: u32 = 90;

/// The thesis, as the report cites it.
const THESIS: &str = "F. Basmaji, Dynamic response of geared system with backlash, PhD thesis, The City University, London, 1983";

/// Writes `dir/report.md` and returns its path.
pub fn write_report(
    dir: &Path,
    meta: &SweepMeta,
    cases: &[CaseResult],
    plots: &[PathBuf],
) -> anyhow::Result<PathBuf> {
    let mut md = String::new();
    let healthy: Vec<CaseResult> = cases.iter().filter(|c| c.is_healthy()).cloned().collect();
    match &meta.rig_file {
        Some(rig) if !meta.held_against_thesis() || healthy.is_empty() => {
            rig_summary(&mut md, meta, rig, cases);
        }
        _ => held_against_thesis(&mut md, meta, &healthy),
    }
    if meta.rig_file.is_some() {
        each_case(&mut md, meta, cases);
    }
    plots_section(&mut md, plots);
    PartialFile::write_whole(&dir.join("report.md"), md)
}

/// The sweep's healthy `cases` held against the thesis: its line-test score, the
/// physics judge's scores and table, the thesis's facts, the spectral findings, the
/// table of lines.
fn held_against_thesis(md: &mut String, meta: &SweepMeta, cases: &[CaseResult]) {
    let (hits, total) = score(cases);
    let _ = writeln!(
        md,
        "# {}: the thesis's findings, point by point\n",
        meta.name
    );
    let score = if total == 0 {
        "no points finished yet".to_string()
    } else {
        format!(
            "**{hits} of {total} = {:.0} %** (target {TARGET_PERCENT} %)",
            100.0 * hits as f64 / total as f64
        )
    };
    let _ = writeln!(
        md,
        "{total} points, held against {THESIS}, ch. IV (Figs 4.34–4.72). A half-order line counts as present when it stands 10 dB above the lines around it in the averaged spectrum of the output-shaft strain (the thesis's chain: gauges, bridge, carrier amplifier, slip rings, anti-alias filter, 5451C). Score of the points against the thesis (half order present from {HALF_ORDER_FROM_RPM} rev/min up at every load, absent below, absent with {HEAVY_LOAD_NM} N m from {VANISHES_FROM_RPM} rev/min): {score}.\n"
    );
    physics(md, cases);
    facts(md, cases);
    findings(md, meta, cases);
    table(md, cases);
}

/// The report's last section: each PNG of `plots`, shown.
pub(super) fn plots_section(md: &mut String, plots: &[PathBuf]) {
    let _ = writeln!(md, "\n## Plots\n");
    for p in plots
        .iter()
        .filter(|p| p.extension().is_some_and(|e| e == "png"))
    {
        let name = p
            .file_name()
            .map(|n| n.to_string_lossy().into_owned())
            .unwrap_or_default();
        let _ = writeln!(md, "![{name}]({name})\n");
    }
}

/// The physics judge's score and its table: each point's motion against the thesis's.
fn physics(md: &mut String, cases: &[CaseResult]) {
    let _ = writeln!(md, "## The motion, judged as physics\n");
    let _ = writeln!(
        md,
        "The thesis's motion: period 1 below {PERIOD_ONE_BELOW_RPM} rev/min, period 2 with a half-order line ≥ 20 dB over the broadband floor from {HALF_ORDER_FROM_RPM} rev/min (period 1 with {HEAVY_LOAD_NM} N m from {VANISHES_FROM_RPM} rev/min); 1000 rev/min is not decided. The judge (`rig::judge`) reads the true output-shaft torque: once-per-revolution samples taken every k revolutions within 5 % of its AC RMS and ≥ 95 % of the band's power on the period's lines make period k; otherwise the 0-1 test for chaos (K ≥ 0.5) tells chaotic from quasi-periodic.\n"
    );
    let mut directions: Vec<Direction> = cases.iter().map(|c| c.direction).collect();
    directions.sort_by_key(|d| *d as u8);
    directions.dedup();
    for direction in &directions {
        let these: Vec<CaseResult> = cases
            .iter()
            .filter(|c| c.direction == *direction)
            .cloned()
            .collect();
        let _ = writeln!(
            md,
            "- {direction}: **{}** move as the thesis saw (target {TARGET_PERCENT} %).",
            decided_share(physics_score(&these))
        );
    }
    if directions.len() > 1 {
        let _ = writeln!(
            md,
            "- The lab's score: **{}** hold the thesis's motion by some approach ({}); the strict score is the run-up's, above (target {TARGET_PERCENT} % for each).",
            decided_share(lab_score(cases)),
            directions
                .iter()
                .map(|d| d.to_string())
                .collect::<Vec<_>>()
                .join(", ")
        );
    }
    motion_lines(md, cases);
    let _ = writeln!(
        md,
        "\nEach cell: the judged motion, the half-order height over the floor (dB; \"≥ {MAX:.0} dB\" where the floor is rounding noise, the judge's cap), the 0-1 test's K; ✓ where it is the thesis's motion, ✗ where not, blank where the thesis decides nothing.\n",
        MAX = rig::judge::MAX_HEIGHT_DB
    );
    motion_table(md, cases);
}

/// "h of n decided points (p %)".
fn decided_share((hits, total): (usize, usize)) -> String {
    let share = if total == 0 {
        0.0
    } else {
        100.0 * hits as f64 / total as f64
    };
    format!("{hits} of {total} decided points ({share:.0} %)")
}

fn motion_table(md: &mut String, cases: &[CaseResult]) {
    let mut columns: Vec<(Direction, f64)> =
        cases.iter().map(|c| (c.direction, c.load_nm)).collect();
    columns.sort_by(|a, b| {
        (a.0 as u8, a.1)
            .partial_cmp(&(b.0 as u8, b.1))
            .unwrap_or(std::cmp::Ordering::Equal)
    });
    columns.dedup();
    let columns: Vec<(String, _)> = columns
        .into_iter()
        .map(|(d, l)| {
            let header = match d {
                Direction::Static => format!("{l} N m"),
                _ => format!("{l} N m {d}"),
            };
            (header, move |c: &CaseResult| {
                c.load_nm == l && c.direction == d
            })
        })
        .collect();
    speed_table(md, &columns, cases, motion_cell);
}

/// A table of `cases` with a row per speed and the given `columns` (a header and which
/// cases of a row are the column's), each cell drawn by `cell` (several joined by " / ",
/// as a point's knocked repeats; "–" where there is none).
fn speed_table(
    md: &mut String,
    columns: &[(String, impl Fn(&CaseResult) -> bool)],
    cases: &[CaseResult],
    cell: impl Fn(&CaseResult) -> String,
) {
    let headers: Vec<&str> = columns.iter().map(|(h, _)| h.as_str()).collect();
    let _ = writeln!(md, "| rev/min | {} |", headers.join(" | "));
    let _ = writeln!(md, "|---|{}", "---|".repeat(columns.len()));
    let mut speeds: Vec<f64> = cases.iter().map(|c| c.rpm).collect();
    speeds.sort_by(f64::total_cmp);
    speeds.dedup();
    for rpm in speeds {
        let cells: Vec<String> = columns
            .iter()
            .map(|(_, here)| {
                let held: Vec<String> = cases
                    .iter()
                    .filter(|c| c.rpm == rpm && here(c))
                    .map(&cell)
                    .collect();
                if held.is_empty() {
                    "–".into()
                } else {
                    held.join(" / ")
                }
            })
            .collect();
        let _ = writeln!(md, "| {rpm} | {} |", cells.join(" | "));
    }
}

/// A line's height over the broadband floor (dB), as "≥ 150 dB" at the judge's cap: there
/// the floor is rounding noise, and no larger number would mean more.
fn height_over_floor(height_db: f64) -> String {
    if height_db >= rig::judge::MAX_HEIGHT_DB - 0.5 {
        format!("≥ {:.0} dB", rig::judge::MAX_HEIGHT_DB)
    } else {
        format!("{height_db:.0} dB")
    }
}

fn motion_cell(c: &CaseResult) -> String {
    let mark = match thesis_motion(c.rpm, c.load_nm) {
        None => "",
        Some(_) if physics_match(c) => " ✓",
        Some(_) => " ✗",
    };
    let height = c.motion.half_order_db.map_or("–".into(), height_over_floor);
    let k = c.motion.chaos_k.map_or("–".into(), |k| format!("{k:.2}"));
    format!("{}, {height}, K {k}{mark}", c.motion.motion)
}

/// The verdict on a finding that `matched` of the grid's `points` for it reproduce.
fn verdict(matched: usize, points: usize) -> &'static str {
    match points {
        0 => "not covered by this grid",
        _ if matched == points => "reproduced",
        _ => "not reproduced",
    }
}

fn findings(md: &mut String, meta: &SweepMeta, cases: &[CaseResult]) {
    let _ = writeln!(md, "## Findings (Basmaji 1983, ch. IV)\n");
    let count = |f: &dyn Fn(&CaseResult) -> bool, g: &dyn Fn(&CaseResult) -> bool| {
        let chosen: Vec<_> = cases.iter().filter(|c| f(c)).collect();
        (chosen.iter().filter(|c| g(c)).count(), chosen.len())
    };
    let (a, an) = count(&|c| c.rpm < HALF_ORDER_FROM_RPM, &|c| !c.half_order_present);
    let _ = writeln!(
        md,
        "1. Below about 1000 rev/min only the running speed and its multiples: {} — no half-order line at {a} of {an} points.",
        verdict(a, an)
    );
    let (b, bn) = count(&|c| thesis_expects_half_order(c.rpm, c.load_nm), &|c| {
        c.half_order_present
    });
    let _ = writeln!(
        md,
        "2. From 1100 rev/min up a half-order line, with and without load: {} — present at {b} of {bn} points.",
        verdict(b, bn)
    );
    let (c, cn) = count(
        &|c| c.load_nm >= HEAVY_LOAD_NM - 1e-6 && c.rpm >= VANISHES_FROM_RPM,
        &|c| !c.half_order_present,
    );
    let (s, sn) = count(
        &|c| c.load_nm >= HEAVY_LOAD_NM - 1e-6 && c.rpm >= VANISHES_FROM_RPM,
        &|c| !c.separates,
    );
    let _ = writeln!(
        md,
        "3. With 5.424 N m the line is gone from 1900 rev/min: {} — absent at {c} of {cn} points. The thesis's reason, the load keeping the teeth together: {} — no separation at {s} of {sn}.",
        verdict(c, cn),
        verdict(s, sn)
    );
    at_1100(md, cases);
    resonance(md, meta, cases);
}

/// Finding 4: the half-order line at 1100 rev/min and the two-revolution period.
fn at_1100(md: &mut String, cases: &[CaseResult]) {
    let there: Vec<_> = cases.iter().filter(|c| c.rpm == 1100.0).collect();
    if there.is_empty() {
        let _ = writeln!(
            md,
            "4. At 1100 rev/min the line lies at 9.17 Hz and the trace repeats every two revolutions: not covered by this grid (no point at 1100 rev/min)."
        );
        return;
    }
    let _ = writeln!(
        md,
        "4. At 1100 rev/min the line lies at 9.17 Hz and the trace repeats every two revolutions: {} of {} loads show it; periods there: {}.",
        there.iter().filter(|c| c.half_order_present).count(),
        there.len(),
        there
            .iter()
            .map(|c| c.regime.to_string())
            .collect::<Vec<_>>()
            .join(", ")
    );
}

/// Finding 5: the once-per-revolution resonance near the measured fundamental, judged only
/// on a grid dense enough around it.
fn resonance(md: &mut String, meta: &SweepMeta, cases: &[CaseResult]) {
    let f1 = meta.natural_hz.first().copied().unwrap_or(f64::NAN);
    let claim = format!(
        "5. The fundamental measured at {MEASURED_FUNDAMENTAL_HZ} Hz, the running speed of the once-per-revolution resonance (≈ {MEASURED_RESONANCE_RPM} rev/min): the linear model's is {f1:.2} Hz;"
    );
    let mut low: Vec<f64> = cases
        .iter()
        .map(|c| c.rpm)
        .filter(|&r| r <= 1000.0)
        .collect();
    low.sort_by(f64::total_cmp);
    low.dedup();
    let band = |side: f64| MEASURED_RESONANCE_RPM * (1.0 + side * RESONANCE_TOLERANCE);
    let spans =
        low.first().is_some_and(|&r| r < band(-1.0)) && low.last().is_some_and(|&r| r > band(1.0));
    if low.len() < RESONANCE_MIN_SPEEDS || !spans {
        let _ = writeln!(
            md,
            "{claim} not covered by this grid ({} speeds up to 1000 rev/min; the resonance needs {RESONANCE_MIN_SPEEDS} or more, from below {:.0} to above {:.0} rev/min).\n",
            low.len(),
            band(-1.0),
            band(1.0)
        );
        return;
    }
    let peaks = first_order_peaks(cases);
    let loaded: Vec<_> = peaks.iter().filter(|(load, _)| *load > 0.0).collect();
    let near = loaded
        .iter()
        .filter(|(_, rpm)| (rpm / MEASURED_RESONANCE_RPM - 1.0).abs() <= RESONANCE_TOLERANCE)
        .count();
    let listed: Vec<String> = peaks
        .iter()
        .map(|(load, rpm)| format!("{rpm:.0} rev/min ({:.2} Hz) at {load} N m", rpm / 60.0))
        .collect();
    let _ = writeln!(
        md,
        "{claim} with backlash the first-order line peaks at {}: {} (loaded peaks within {:.0} % of {MEASURED_RESONANCE_RPM} rev/min).\n",
        listed.join(", "),
        verdict(near, loaded.len()),
        RESONANCE_TOLERANCE * 100.0
    );
}

/// Per load, the speed (rev/min) up to 1000 rev/min at which the first-order line is
/// largest: the once-per-revolution resonance, below the subharmonic range.
fn first_order_peaks(cases: &[CaseResult]) -> Vec<(f64, f64)> {
    let mut loads: Vec<f64> = cases.iter().map(|c| c.load_nm).collect();
    loads.sort_by(f64::total_cmp);
    loads.dedup();
    loads
        .into_iter()
        .filter_map(|load| {
            cases
                .iter()
                .filter(|c| c.load_nm == load && c.rpm <= 1000.0 && c.first_order.is_finite())
                .max_by(|a, b| a.first_order.total_cmp(&b.first_order))
                .map(|c| (load, c.rpm))
        })
        .collect()
}

fn table(md: &mut String, cases: &[CaseResult]) {
    let mut loads: Vec<f64> = cases.iter().map(|c| c.load_nm).collect();
    loads.sort_by(f64::total_cmp);
    loads.dedup();
    let _ = writeln!(
        md,
        "## Half-order line by speed (rows) and load (columns)\n"
    );
    let _ = writeln!(
        md,
        "Each cell: height of the half-order line above the floor (dB), the regime; ✓ where the verdict matches the thesis, ✗ where not.\n"
    );
    // One case a cell: the first approach the sweep ran (the run-up where there is one).
    let first = cases.first().map(|c| c.direction);
    let columns: Vec<(String, _)> = loads
        .into_iter()
        .map(|l| {
            (format!("{l} N m"), move |c: &CaseResult| {
                c.load_nm == l && Some(c.direction) == first
            })
        })
        .collect();
    speed_table(md, &columns, cases, |c| {
        let ok = c.half_order_present == thesis_expects_half_order(c.rpm, c.load_nm);
        format!(
            "{:.0} dB, {} {}",
            c.half_order_db,
            c.regime,
            if ok { "✓" } else { "✗" }
        )
    });
}
