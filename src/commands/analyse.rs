//! `testrig analyse`: a WAV file through anti-alias filter, ADC and the Fourier analyser,
//! with the ground truth of which lines are aliases.

use std::path::PathBuf;

use anyhow::{Context, bail};
use instruments::{KeyboardProgram, LowPassSpec, Sampling};

use crate::cli::AnalyseArgs;
use testrig::chain::{AdcChoice, AnalyserSetting, AnalyserSetup, AnalyserWords, LowPassWords};
use testrig::chain::{Instrument, Measurement, Truth, anti_aliased};
use testrig::chain::{SpectrumFacts, spectrum_metadata};
use testrig::plots::{SpectrumPlot, write_spectrum_plots};
use testrig::recording::{Metadata, PartialFile, start_journal, write_spectrum_csv};
use testrig::runtime::{clear_previous_run, write_command_manifest};
use testrig::wav_input::{WavSignal, read_signal};

pub fn run(args: &AnalyseArgs) -> anyhow::Result<()> {
    let wav = read_signal(&args.file, &args.channel, args.start, args.length)?;
    let range = adc_range(args.range, &wav)?;
    let words = AnalyserWords {
        fmax_hz: args.fmax,
        block: args.block,
        window: args.window,
        averages: args.averages,
        overlap: args.overlap / 100.0,
        sampling: Sampling::from(args.sampling),
        adc: AdcChoice {
            bits: args.bits,
            range_v: range.value,
            dither_seed: None,
        },
    };
    let setup = words.set_up(wav.rate_hz).map_err(|e| {
        let flag = match e.setting() {
            AnalyserSetting::Block => format!("--block {}", args.block),
            AnalyserSetting::FmaxHz => format!("--fmax {}", args.fmax),
            AnalyserSetting::Averages => format!("--averages {}", args.averages),
            AnalyserSetting::OverlapPct => format!("--overlap {}", args.overlap),
            AnalyserSetting::Adc => format!("--bits {}", args.bits),
        };
        anyhow::anyhow!("{flag}: {e}")
    })?;
    let filter = filter_spec(args, wav.rate_hz)?;
    let analogue = anti_aliased(&wav.samples, wav.rate_hz, filter).context("--filter/--cutoff")?;
    std::fs::create_dir_all(&args.out)
        .with_context(|| format!("--out {}: cannot create the folder", args.out.display()))?;
    clear_previous_run(&args.out, "analyse", args.replace)?;
    start_journal(&args.out, "analyse")?;
    let (overloads, files) = match &args.program {
        Some(program) => run_program(args, program, setup, &analogue)?,
        None => run_analyser(args, setup, &wav, &analogue, filter, &range)?,
    };
    let details = serde_json::json!({
        "file": args.file.display().to_string(), "channel": args.channel,
        "fmax_hz": args.fmax, "block": args.block, "averages": args.averages,
    });
    write_command_manifest(&args.out, "analyse", &files, details)?;
    warn_of_overloads(overloads, &range, &wav.unit);
    Ok(())
}

/// The averaged spectrum of the analogue signal with the alias truth: spectrum.csv and
/// plots; returns the ADC's overloads.
fn run_analyser(
    args: &AnalyseArgs,
    setup: AnalyserSetup,
    wav: &WavSignal,
    analogue: &[f64],
    filter: Option<LowPassSpec>,
    range: &AdcRange,
) -> anyhow::Result<(u64, Vec<PathBuf>)> {
    let settings = setup.settings;
    let ratio = setup.adc_settings.ratio;
    let mut measurement = Measurement::new(setup, Truth::Kept);
    measurement.push(analogue);
    let Some(spectrum) = measurement.spectrum() else {
        bail!(
            "{} (--start {} s, --length {}): {} samples at {} Hz are fewer than one block of {} ADC samples ({:.3} s)",
            args.file.display(),
            args.start,
            args.length
                .map_or("to the end".into(), |l| format!("{l} s")),
            wav.samples.len(),
            wav.rate_hz,
            args.block,
            args.block as f64 * ratio / wav.rate_hz
        );
    };
    let (lines, alias_of, count) = (spectrum.lines, spectrum.alias_of, spectrum.averages);
    let overloads = spectrum.adc_overloads;
    let filter = match Instrument::LowPass(filter).describe().as_str() {
        "none" => "no filter".to_string(),
        described => described.to_string(),
    };
    let metadata = metadata(args, &measurement, wav, range, &filter);
    let csv = args.out.join("spectrum.csv");
    write_spectrum_csv(&csv, &metadata, &lines, &alias_of)?;
    let overload = match overloads {
        0 => String::new(),
        n => format!(" (ADC OVERLOADED on {n} samples)"),
    };
    let title = format!(
        "{}{}: {} av., {} window, {filter}, N = {}{overload}",
        args.file
            .file_name()
            .map_or_else(|| "input".into(), |n| n.to_string_lossy()),
        wav.name.as_ref().map_or(String::new(), |n| format!(" {n}")),
        count,
        settings.window.name(),
        args.block
    );
    let mut files = vec![csv];
    files.extend(write_spectrum_plots(
        &args.out.join("spectrum"),
        &SpectrumPlot {
            title: &title,
            unit: &wav.unit,
            lines: &lines,
            alias_of: &alias_of,
            running_hz: args.rpm.map(|rpm| rpm / 60.0),
        },
    )?);
    let fewer = if count < args.averages {
        let block_s = args.block as f64 * ratio / wav.rate_hz;
        format!(
            " (the {:.1} s analysed hold {count} blocks of {block_s:.2} s: a shorter --block or more --overlap gives more)",
            wav.samples.len() as f64 / wav.rate_hz
        )
    } else {
        String::new()
    };
    println!(
        "{} lines to {}; {} of {} averages{fewer}; ADC range ±{} {} ({}), {} overloads",
        lines.len(),
        args.out.display(),
        count,
        args.averages,
        range.value,
        wav.unit,
        range.source,
        overloads
    );
    Ok((overloads, files))
}

/// An HP 5451C keyboard program on the ADC samples of `analogue`: each DISPLAY as
/// display-NN.csv; returns the ADC's overloads.
fn run_program(
    args: &AnalyseArgs,
    path: &std::path::Path,
    mut setup: AnalyserSetup,
    analogue: &[f64],
) -> anyhow::Result<(u64, Vec<PathBuf>)> {
    let settings = &setup.settings;
    let mut samples = Vec::with_capacity(analogue.len() / setup.adc_settings.ratio as usize + 1);
    setup.adc.convert(analogue, &mut samples);
    let text = std::fs::read_to_string(path)
        .with_context(|| format!("--program {}: cannot read", path.display()))?;
    let program =
        KeyboardProgram::parse(&text).with_context(|| format!("--program {}", path.display()))?;
    let displays = program
        .run(settings, &samples)
        .with_context(|| format!("--program {}", path.display()))?;
    let mut files = Vec::new();
    for (k, display) in displays.iter().enumerate() {
        let file = PartialFile::new(&args.out.join(format!("display-{:02}.csv", k + 1)));
        let mut csv = csv::Writer::from_writer(file.create()?);
        csv.write_record(["frequency_hz", "value"])?;
        for line in display {
            csv.write_record([line.frequency_hz.to_string(), format!("{:e}", line.value)])?;
        }
        csv.flush()
            .with_context(|| format!("cannot write {}", file.path().display()))?;
        drop(csv);
        files.push(file.commit()?);
    }
    println!(
        "{}: {} displays to {} (display-NN.csv: the block as shown, in dB after LOG)",
        path.display(),
        displays.len(),
        args.out.display()
    );
    Ok((setup.adc.overloads(), files))
}

/// The ADC's ±range and where it came from.
struct AdcRange {
    /// ±range in the signal's unit.
    value: f64,
    /// Why this range: the flag, the recording's full scale, or the signal's peak.
    source: &'static str,
}

/// `--range`, else the recording's full scale, else the 1-2-5 step above the peak.
fn adc_range(given: Option<f64>, wav: &WavSignal) -> anyhow::Result<AdcRange> {
    if let Some(value) = given {
        if !(value.is_finite() && value > 0.0) {
            bail!("--range {value}: a full scale > 0 in the signal's unit");
        }
        return Ok(AdcRange {
            value,
            source: "--range",
        });
    }
    if let Some(value) = wav.full_scale {
        return Ok(AdcRange {
            value,
            source: "the recording's full scale",
        });
    }
    let peak = wav.samples.iter().fold(0.0_f64, |m, s| m.max(s.abs()));
    Ok(AdcRange {
        value: one_two_five_above(peak),
        source: "the 1-2-5 step above the section's peak",
    })
}

/// The smallest of 1, 2, 5 × 10^k above `peak` (1 for a silent or non-finite signal).
fn one_two_five_above(peak: f64) -> f64 {
    if !(peak.is_finite() && peak > 0.0) {
        return 1.0;
    }
    let decade = 10f64.powf(peak.log10().floor());
    [1.0, 2.0, 5.0, 10.0, 20.0]
        .iter()
        .map(|m| m * decade)
        .find(|&v| v > peak)
        .unwrap_or(20.0 * decade)
}

fn warn_of_overloads(overloads: u64, range: &AdcRange, unit: &str) {
    if overloads > 0 {
        eprintln!(
            "warning: the ADC overloaded on {overloads} samples at ±{} {unit} ({}): raise --range",
            range.value, range.source
        );
    }
}

/// The anti-alias filter `--filter`, `--cutoff` ask for (the cut-off left out follows
/// `--fmax`) on a recording at `rate_hz`.
fn filter_spec(args: &AnalyseArgs, rate_hz: f64) -> anyhow::Result<Option<LowPassSpec>> {
    let words = LowPassWords {
        kind: args.filter.kind,
        order: args.filter.order,
        cutoff_hz: args.cutoff,
    };
    words
        .spec(args.fmax, rate_hz)
        .map_err(|e| anyhow::anyhow!("--cutoff: {e}"))
}

/// The spectrum's `# key: value` lines: the file and section analysed, then the
/// measurement's settings and facts.
fn metadata(
    args: &AnalyseArgs,
    measurement: &Measurement,
    wav: &WavSignal,
    range: &AdcRange,
    filter: &str,
) -> Metadata {
    let overloads = measurement.overloads();
    let section_s = wav.samples.len() as f64 / wav.rate_hz;
    let head = vec![
        ("file", args.file.display().to_string()),
        (
            "channel",
            match &wav.name {
                Some(name) => format!("{} ({name}, {})", wav.channel, wav.unit),
                None => wav.channel.to_string(),
            },
        ),
        (
            "section_s",
            format!("{} to {}", args.start, args.start + section_s),
        ),
        ("file_rate_hz", wav.rate_hz.to_string()),
    ];
    spectrum_metadata(
        head,
        SpectrumFacts {
            settings: &measurement.setup.settings,
            enbw_hz: measurement.setup.analyser.enbw_hz(),
            averages_done: measurement.average_count(),
            filter: filter.to_string(),
            adc: format!(
                "{} bits over +-{} {} ({}), {overloads} overloads",
                args.bits, range.value, wav.unit, range.source
            ),
            unit: &wav.unit,
        },
    )
}
