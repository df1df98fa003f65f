//! `testrig analyse`: a WAV file through anti-alias filter, ADC and the Fourier analyser,
//! with the ground truth of which lines are aliases.

use anyhow::{Context, bail};
use instruments::{
    Adc, AdcSettings, AliasTruth, Analyser, AnalyserSettings, AntiAliasFilter, Averaging, Block,
    FilterKind, LowPassSpec, Sampling, Spectrum, Window,
};

use crate::cli::AnalyseArgs;
use crate::wav_input::read_channel;
use testrig::plots::{SpectrumPlot, write_spectrum_plots};
use testrig::recording::{Metadata, write_spectrum_csv};

pub fn run(args: &AnalyseArgs) -> anyhow::Result<()> {
    let settings = analyser_settings(args)?;
    let wav = read_channel(&args.file, args.channel)?;
    let ratio = wav.rate_hz / settings.sample_rate_hz();
    if ratio < 1.0 {
        bail!(
            "--fmax {}: the ADC rate {} Hz exceeds the file's rate {} Hz",
            args.fmax,
            settings.sample_rate_hz(),
            wav.rate_hz
        );
    }
    let filter_spec = filter_spec(&args.filter, args.cutoff.unwrap_or(args.fmax))?;
    let mut filter = AntiAliasFilter::new(filter_spec, wav.rate_hz).context("--filter/--cutoff")?;
    let mut analogue = vec![0.0; wav.samples.len()];
    filter.process(&wav.samples, &mut analogue);
    let mut adc = Adc::new(AdcSettings {
        ratio,
        bits: args.bits,
        range_v: args.range,
        dither_seed: None,
    })
    .context("--bits/--range")?;
    let mut samples = Vec::with_capacity((analogue.len() as f64 / ratio) as usize + 1);
    adc.convert(&analogue, &mut samples);
    let mut analyser = Analyser::new(settings).context("--block/--fmax/--averages/--overlap")?;
    analyser.push(&samples);
    let count = analyser.average_count();
    if count == 0 {
        bail!(
            "{}: {} samples at {} Hz are fewer than one block of {} ADC samples ({:.3} s)",
            args.file.display(),
            wav.samples.len(),
            wav.rate_hz,
            args.block,
            args.block as f64 * ratio / wav.rate_hz
        );
    }
    let mut truth = AliasTruth::new(args.block, ratio, wav.rate_hz, settings.window)?;
    let span = truth.span();
    for b in 0..count {
        let start = (b as f64 * settings.hop() as f64 * ratio).round() as usize;
        if let Some(block) = analogue.get(start..start + span) {
            truth.add(block);
        }
    }
    let lines = analyser.display();
    let floor = adc.quantisation_line_power(analyser.enbw_hz(), settings.sample_rate_hz());
    let alias_of = truth.flags(lines.len(), floor);
    std::fs::create_dir_all(&args.out)
        .with_context(|| format!("--out {}: cannot create the folder", args.out.display()))?;
    let metadata = metadata(
        args,
        &settings,
        &analyser,
        wav.rate_hz,
        count,
        adc.overloads(),
    );
    write_spectrum_csv(&args.out.join("spectrum.csv"), &metadata, &lines, &alias_of)?;
    let title = format!(
        "{}: {} averages, {} window, N = {}",
        args.file
            .file_name()
            .map_or_else(|| "input".into(), |n| n.to_string_lossy()),
        count,
        settings.window.name(),
        args.block
    );
    write_spectrum_plots(
        &args.out.join("spectrum"),
        &SpectrumPlot {
            title: &title,
            unit: "WAV unit",
            lines: &lines,
            alias_of: &alias_of,
            running_hz: None,
        },
    )?;
    println!(
        "{} lines to {}; {} of {} averages; {} ADC overloads",
        lines.len(),
        args.out.display(),
        count,
        args.averages,
        adc.overloads()
    );
    Ok(())
}

fn analyser_settings(args: &AnalyseArgs) -> anyhow::Result<AnalyserSettings> {
    let window = Window::parse(&args.window)
        .with_context(|| format!("--window {}: one of {}", args.window, Window::NAMES))?;
    let sampling = match args.sampling.as_str() {
        "thesis" => Sampling::Thesis,
        "2.56" | "modern" => Sampling::Modern,
        other => bail!("--sampling {other}: thesis (fs = 2 Fmax) or 2.56 (fs = 2.56 Fmax)"),
    };
    if !(0.0..100.0).contains(&args.overlap) {
        bail!("--overlap {}: a percentage in [0, 100)", args.overlap);
    }
    Ok(AnalyserSettings {
        block: args.block,
        fmax_hz: args.fmax,
        sampling,
        window,
        spectrum: Spectrum::Power,
        averaging: Averaging::Linear,
        averages: args.averages,
        overlap: args.overlap / 100.0,
    })
}

fn filter_spec(text: &str, cutoff_hz: f64) -> anyhow::Result<Option<LowPassSpec>> {
    if text == "none" {
        return Ok(None);
    }
    let (kind, order) = text
        .split_once(':')
        .with_context(|| format!("--filter {text}: none, butterworth:ORDER or bessel:ORDER"))?;
    let kind = match kind {
        "butterworth" => FilterKind::Butterworth,
        "bessel" => FilterKind::Bessel,
        other => bail!("--filter {text}: `{other}` is not butterworth or bessel"),
    };
    let order = order
        .parse()
        .with_context(|| format!("--filter {text}: the order must be a whole number"))?;
    Ok(Some(LowPassSpec {
        kind,
        order,
        cutoff_hz,
    }))
}

fn metadata(
    args: &AnalyseArgs,
    settings: &AnalyserSettings,
    analyser: &Analyser,
    file_rate_hz: f64,
    count: usize,
    overloads: u64,
) -> Metadata {
    vec![
        ("file", args.file.display().to_string()),
        ("channel", args.channel.to_string()),
        ("file_rate_hz", file_rate_hz.to_string()),
        ("fs_hz", settings.sample_rate_hz().to_string()),
        ("n", settings.block.to_string()),
        ("fmax_hz", settings.fmax_hz.to_string()),
        ("sampling", args.sampling.clone()),
        ("window", settings.window.name().to_string()),
        ("enbw_hz", analyser.enbw_hz().to_string()),
        (
            "averages",
            format!(
                "{count} of {} requested, linear (sum then divide)",
                settings.averages
            ),
        ),
        ("overlap_pct", args.overlap.to_string()),
        (
            "filter",
            format!(
                "{} cut-off {} Hz",
                args.filter,
                args.cutoff.unwrap_or(args.fmax)
            ),
        ),
        (
            "adc",
            format!(
                "{} bits over +-{} , {overloads} overloads",
                args.bits, args.range
            ),
        ),
        (
            "scaling",
            Spectrum::Power.scaling().replace("unit", "WAV unit"),
        ),
        (
            "alias_of_hz",
            "true frequency of a component aliased onto the line; empty for a real component or one below the ADC's quantisation noise per line"
                .to_string(),
        ),
    ]
}
