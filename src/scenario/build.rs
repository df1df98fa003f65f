//! From a parsed scenario file to a checked [`Plan`].

use super::read_chain::{ChainSetting, analyser_plan, chain_plan, record_plan};
use super::read_rig::{plan_rig, schedule_and_measures};
use super::read_stages::read_signal_among;
use super::rig_chain::rig_chain;
use super::run_plan::{Plan, RecordPlan};
use super::scenario_toml::ScenarioFile;
use super::source::ScenarioSource;
use super::values::Positive;
use crate::vocabulary::choices::WavFormat;
use crate::vocabulary::limits::check_simulated_s;

/// Run-time choices from the command line that override the file.
#[derive(Clone, Copy, Debug, Default)]
pub struct CommandLine {
    /// `--duration S`.
    pub duration_s: Option<f64>,
    /// `--seed N`.
    pub seed: Option<u64>,
}

/// Reads, parses and checks the scenario source into a plan.
pub fn build(src: &ScenarioSource, command_line: CommandLine) -> anyhow::Result<Plan> {
    let file: ScenarioFile = src.parse()?;
    let rate_hz = stream_rate_hz(src, &file.rate_hz)?;
    for (value, field, most) in [
        (&file.block_samples, "block_samples", MAX_BLOCK_SAMPLES),
        (&file.queue_blocks, "queue_blocks", MAX_QUEUE_BLOCKS),
    ] {
        if !(1..=most).contains(value.get_ref()) {
            return Err(src.error(value.span(), field, format!("must lie in 1..={most}")));
        }
    }
    let seed = command_line.seed.unwrap_or(file.seed);
    let rig = plan_rig(src, &file.rig)?;
    let (schedule, measures, survey_s) = schedule_and_measures(src, &file)?;
    rig.check_load(schedule.load_nm.range().1)
        .map_err(|message| src.error(0..0, "load_nm", message))?;
    let duration_s = match (command_line.duration_s, &file.duration_s, survey_s) {
        (Some(d), _, _) => d,
        (None, Some(d), _) => d.get_ref().0,
        (None, None, Some(d)) => d,
        (None, None, None) => {
            return Err(src.error(0..0, "duration_s", "missing: the simulated run length (s)"));
        }
    };
    if let Err(message) = check_simulated_s(duration_s, false) {
        let span = match (&command_line.duration_s, &file.duration_s) {
            (None, Some(d)) => d.span(),
            _ => 0..0,
        };
        return Err(src.error(span, "duration_s", message));
    }
    let analyser = match &file.analyser {
        Some(a) => Some(analyser_plan(src, a, rate_hz, seed)?),
        None => None,
    };
    let band_hz = analyser.as_ref().map(|a| a.settings.fmax_hz);
    let plant = crate::rig_roles::plant_signals(&rig.topology);
    let setting = ChainSetting {
        plant: &plant,
        rate_hz,
        seed,
        band_hz,
    };
    let mut chain = chain_plan(src, &file.chain, setting)?;
    chain = rig_chain(src, &rig.topology, &chain)?;
    let names = chain.stages.signal_names_on(&plant);
    if let (Some(a), Some(written)) = (&analyser, &file.analyser) {
        let input = written.input.as_ref();
        read_signal_among(src, &names, input, "analyser.input", &a.input)?;
    }
    let record = match &file.record {
        Some(r) => Some(record_plan(src, r, &chain, &names)?),
        None => None,
    };
    if let (Some(r), Some(written)) = (&record, &file.record)
        && r.wav.is_some()
    {
        let recorded_hz = rate_hz / r.decimate as f64;
        if recorded_hz < 1.0 || recorded_hz.fract() != 0.0 || recorded_hz > f64::from(u32::MAX) {
            return Err(src.error(
                written.decimate.span(),
                "record.decimate",
                format!(
                    "{rate_hz} Hz / {} = {recorded_hz} Hz: a WAV file needs a whole sample rate of at least 1 Hz",
                    r.decimate
                ),
            ));
        }
        let span = written.signals.first().map_or(0..0, |s| s.span());
        check_wav_size(src, r, duration_s * rate_hz, span)?;
    }
    Ok(Plan {
        name: file.name,
        description: file.description,
        text: src.text.clone(),
        seed,
        duration_s,
        rate_hz,
        block_samples: *file.block_samples.get_ref(),
        overflow: file.overflow,
        queue_blocks: *file.queue_blocks.get_ref(),
        rig,
        schedule,
        measures,
        is_survey: file.survey.is_some(),
        chain,
        analyser,
        record,
        live_ceiling: file.live.as_ref().map(|l| rig::LiveCeiling {
            speed_rpm: l.max_speed_rpm.0,
            oscillating_load_hz: l.max_oscillating_load_hz.0,
        }),
        commands: file.command,
    })
}

/// Most samples in one block between threads (each channel of a frame holds this many).
pub const MAX_BLOCK_SAMPLES: usize = 1 << 20;
/// Most blocks a queue between threads holds.
pub const MAX_QUEUE_BLOCKS: usize = 1024;

/// Slowest stream rate a scenario accepts (Hz): the plant's own lower bound.
pub const MIN_RATE_HZ: f64 = 100.0;
/// Fastest stream rate a scenario accepts (Hz): the plant's own upper bound.
pub const MAX_RATE_HZ: f64 = 1.0e7;

/// The `rate_hz` of a scenario or sweep, checked against the plant's bounds.
pub fn stream_rate_hz(src: &ScenarioSource, rate: &toml::Spanned<Positive>) -> anyhow::Result<f64> {
    let rate_hz = rate.get_ref().0;
    if (MIN_RATE_HZ..=MAX_RATE_HZ).contains(&rate_hz) {
        Ok(rate_hz)
    } else {
        Err(src.error(
            rate.span(),
            "rate_hz",
            format!("{rate_hz} Hz: the stream rate lies in [{MIN_RATE_HZ}, {MAX_RATE_HZ}] Hz"),
        ))
    }
}

/// Largest WAV data a RIFF size field can describe (bytes), less room for the header.
const WAV_LIMIT_BYTES: f64 = 4_294_967_295.0 - 1024.0;

/// A WAV recording must fit the 4 GiB a RIFF file can hold (hound does not guard it).
fn check_wav_size(
    src: &ScenarioSource,
    record: &RecordPlan,
    samples: f64,
    span: std::ops::Range<usize>,
) -> anyhow::Result<()> {
    let bytes_per_sample = match record.wav {
        Some(WavFormat::Int24) => 3.0,
        _ => 4.0,
    };
    let frames = (samples / record.decimate as f64).ceil();
    let bytes = frames * record.signals.len() as f64 * bytes_per_sample;
    if bytes > WAV_LIMIT_BYTES {
        return Err(src.error(
            span,
            "record.signals",
            format!(
                "a WAV file of {:.1} GiB: beyond the 4 GiB a WAV file can hold; record fewer signals, raise decimate, shorten the run, or use csv/uff58",
                bytes / 1_073_741_824.0
            ),
        ));
    }
    Ok(())
}
