//! `testrig panel`: the rig run live, paced, with a front panel in the browser and the
//! JSON API for scripts; on Quit or a stop signal every file is closed and the manifest
//! and the session (a scenario that replays it) are written.

use std::path::PathBuf;
use std::process::ExitCode;

use anyhow::{Context, bail};
use rig::LiveCeiling;
use std::io::Write;

use testrig::panel::{PanelInfo, PanelServer, ScpiRack, ScpiServer, scpi_rack};
use testrig::panel::{Session, commands_toml, session_head};
use testrig::recording::PartialFile;
use testrig::runtime::Ending;
use testrig::runtime::SharedStatus;
use testrig::runtime::clear_previous_run;
use testrig::runtime::run_with_status;
use testrig::runtime::{Pace, RunOptions, StopSignals, write_manifest};
use testrig::scenario::{CommandLine, Plan, ScenarioSource, apply_override, build};
use testrig::vocabulary::ControlHandle;
use testrig::vocabulary::{DEFAULT_LIVE_CEILING, MAX_SIMULATED_S};

use crate::cli::PanelArgs;

/// Starts `path` (`session.toml`) as the session's journal: the scenario as run, then each
/// command appended and written through the moment it takes effect, so that a session
/// killed (`kill -9`, a crash) keeps every command it carried out. The session's end
/// writes the file whole, with its length.
fn journal_session(
    path: &std::path::Path,
    plan: &Plan,
    ceiling: LiveCeiling,
    control: &ControlHandle,
) -> anyhow::Result<()> {
    let cannot = |e: std::io::Error| anyhow::anyhow!("cannot write {}: {e}", path.display());
    if let Some(dir) = path.parent() {
        std::fs::create_dir_all(dir).map_err(cannot)?;
    }
    std::fs::write(path, session_head(&plan.text, plan.seed, ceiling)?).map_err(cannot)?;
    let mut file = std::fs::OpenOptions::new()
        .append(true)
        .open(path)
        .map_err(cannot)?;
    let shown = path.display().to_string();
    control.journal_to(move |command| {
        let written = commands_toml(std::slice::from_ref(command))
            .and_then(|text| Ok(file.write_all(text.as_bytes())?));
        if let Err(e) = written {
            eprintln!("warning: cannot append a command to {shown}: {e:#}");
        }
    });
    Ok(())
}

/// The bundled scenario, used when none is given.
const BUNDLED: &str = include_str!("../../scenarios/panel.toml");
/// Where the bundled scenario lives in the source tree (named in messages and the manifest).
const BUNDLED_PATH: &str = "scenarios/panel.toml";

pub fn run(args: &PanelArgs) -> anyhow::Result<ExitCode> {
    let pace = match args.pace {
        Pace::Factor(f) => Pace::Factor(f),
        Pace::Max => {
            bail!("--pace max: 1 (real time) or a factor from 0.001 to 1e6; a panel is paced")
        }
    };
    let (path, mut source) = scenario_source(args)?;
    let mut plan = build(&source, CommandLine::default())?;
    let ceiling = *plan.live_ceiling.get_or_insert(DEFAULT_LIVE_CEILING);
    // Runs until Quit or a signal: as long as any run may be.
    plan.duration_s = MAX_SIMULATED_S;
    source.text = plan.text.clone();
    clear_previous_run(&args.out, &plan.name, args.replace)?;
    let (control, requests) = ControlHandle::new();
    let session_path = args.out.join("session.toml");
    journal_session(&session_path, &plan, ceiling, &control)?;
    let status = SharedStatus::default();
    let server = PanelServer::start(
        args.listen,
        control.clone(),
        status.clone(),
        info(&plan, ceiling, pace),
    )?;
    match &server.token {
        None => println!(
            "testrig panel: http://{}/ (Quit on the page, or Ctrl-C, ends the session)",
            server.address
        ),
        Some(token) => {
            println!(
                "testrig panel: http://{}/?token={token} (Quit on the page, or Ctrl-C, ends the session)",
                server.address
            );
            eprintln!(
                "warning: --listen {}: the panel is reachable from other machines; the API answers only with the token in the URL above, over plain HTTP (docs/security.md)",
                args.listen
            );
        }
    }
    let scpi = match args.scpi {
        Some(address) => Some(start_scpi(address, &plan, ceiling, &control, &status)?),
        None => None,
    };
    let signals = StopSignals::install().context("cannot install the signal handlers")?;
    let options = RunOptions {
        pace,
        out: args.out.clone(),
        stop: signals.flag(),
        console: false,
        control: Some(requests),
        replace: args.replace,
    };
    let result = run_with_status(&plan, &options, status);
    server.shut_down();
    if let Some(scpi) = scpi {
        scpi.shut_down();
    }
    let result = result?;
    let session = Session {
        scenario_text: &plan.text,
        duration_s: result.simulated_s(),
        seed: plan.seed,
        ceiling,
        commands: &control.session(),
    };
    PartialFile::write_whole(&session_path, session.to_toml()?)?;
    let failed = !result.failures().is_empty();
    // A session ends by Quit (completed) or by a signal (interrupted), unless it failed.
    let ending = if failed {
        Ending::Failed
    } else if signals.received().is_some() {
        Ending::Interrupted
    } else {
        Ending::Completed
    };
    write_manifest(&args.out, &path, &plan, pace, &result, ending)?;
    println!(
        "testrig panel: {:.1} s simulated; files, manifest.json and session.toml (replay: testrig run {} --pace max --out DIR) in {}",
        result.simulated_s(),
        session_path.display(),
        args.out.display()
    );
    if control.refused_busy() > 0 {
        eprintln!(
            "warning: {} commands were refused because {} already waited for the rig (a flood)",
            control.refused_busy(),
            testrig::vocabulary::MAX_QUEUED_COMMANDS
        );
    }
    if failed {
        let all = result.failures();
        bail!("{}", all.join("; "));
    }
    Ok(ExitCode::SUCCESS)
}

/// The scenario given, or the bundled one; `--set` items applied.
fn scenario_source(args: &PanelArgs) -> anyhow::Result<(PathBuf, ScenarioSource)> {
    let (path, mut source) = match &args.scenario {
        Some(path) => (path.clone(), ScenarioSource::read(path)?),
        None => {
            let path = PathBuf::from(BUNDLED_PATH);
            let source = ScenarioSource {
                path: path.clone(),
                text: BUNDLED.to_string(),
            };
            (path, source)
        }
    };
    for item in &args.overrides {
        source.text = apply_override(&source.text, item)?;
    }
    Ok((path, source))
}

fn info(plan: &Plan, ceiling: LiveCeiling, pace: Pace) -> PanelInfo {
    PanelInfo {
        scenario: plan.name.clone(),
        rate_hz: plan.rate_hz,
        pace: pace.label(),
        max_speed_rpm: ceiling.speed_rpm,
        max_load_nm: plan.rig.max_load_nm(),
        max_oscillating_load_hz: ceiling.oscillating_load_hz,
        analyser: plan.analyser.is_some(),
        scope: plan.chain.scope.is_some(),
        record: plan.record.is_some(),
    }
}

/// Starts the SCPI server on the live rig, printing its VISA address (and the token
/// beyond loopback).
fn start_scpi(
    address: std::net::SocketAddr,
    plan: &Plan,
    ceiling: LiveCeiling,
    control: &ControlHandle,
    status: &SharedStatus,
) -> anyhow::Result<ScpiServer> {
    let rack: ScpiRack = scpi_rack(plan, ceiling, control.clone(), status.clone());
    let server = ScpiServer::start(address, rack)?;
    let visa = format!(
        "TCPIP::{}::{}::SOCKET",
        server.address.ip(),
        server.address.port()
    );
    match &server.token {
        None => println!("testrig panel: SCPI at {visa} (read termination \\n; docs/scpi.md)"),
        Some(token) => {
            println!(
                "testrig panel: SCPI at {visa}; send SYSTem:PASSword \"{token}\" first (docs/scpi.md)"
            );
            eprintln!(
                "warning: --scpi {address}: SCPI is reachable from other machines, in plain text; only the token unlocks it (docs/security.md)"
            );
        }
    }
    Ok(server)
}
