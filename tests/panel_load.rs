//! The panel under load for a minute (issue 23): 200 WebSocket clients streaming the
//! state, 1 000 idle sockets and a flood of commands against a rig paced in real time.
//! The plant keeps every block on time (0 overruns), the server's memory stays bounded,
//! and it answers normally afterwards. It takes a minute, so `cargo test` leaves it out;
//! `.ci/run` runs it:
//!
//!     cargo test --test panel_load -- --ignored --nocapture
//!
//! `TESTRIG_LOAD_S` sets another length (s).

mod common;
mod panel_support;

use std::net::TcpStream;
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};
use std::time::{Duration, Instant};

use common::folder;
use panel_support::{Panel, http, try_http};

const WS_CLIENTS: usize = 200;
const IDLE_SOCKETS: usize = 1000;
const FLOODERS: usize = 4;

/// Resident memory of process `pid` (MiB), from /proc.
fn rss_mib(pid: u32) -> f64 {
    let status = std::fs::read_to_string(format!("/proc/{pid}/status")).unwrap_or_default();
    status
        .lines()
        .find_map(|l| l.strip_prefix("VmRSS:"))
        .and_then(|v| v.split_whitespace().next()?.parse::<f64>().ok())
        .map_or(f64::NAN, |kib| kib / 1024.0)
}

/// One WebSocket client: counts the states it receives until `stop`.
fn ws_client(address: std::net::SocketAddr, stop: Arc<AtomicBool>, got: Arc<AtomicU64>) {
    let Ok((mut ws, _)) = tungstenite::connect(format!("ws://{address}/api/stream")) else {
        return;
    };
    if let tungstenite::stream::MaybeTlsStream::Plain(s) = ws.get_ref() {
        let _ = s.set_read_timeout(Some(Duration::from_secs(2)));
    }
    while !stop.load(Ordering::Relaxed) {
        match ws.read() {
            Ok(tungstenite::Message::Text(_)) => {
                got.fetch_add(1, Ordering::Relaxed);
            }
            Ok(_) => {}
            Err(tungstenite::Error::Io(e))
                if matches!(
                    e.kind(),
                    std::io::ErrorKind::WouldBlock | std::io::ErrorKind::TimedOut
                ) => {}
            Err(_) => return,
        }
    }
    let _ = ws.close(None);
}

/// One flooder: sends speed commands back to back until `stop`; counts the answers by
/// status (200, 400 busy or refused, 503 no room — a connection the server closed before
/// taking the request counts as no room too).
fn flooder(address: std::net::SocketAddr, stop: Arc<AtomicBool>, counts: Arc<[AtomicU64; 3]>) {
    let mut k = 0u64;
    while !stop.load(Ordering::Relaxed) {
        let rpm = if k.is_multiple_of(2) { 1250 } else { 1300 };
        k += 1;
        let body = format!("{{\"cmd\": \"set_speed\", \"rpm\": {rpm}}}");
        let slot = match try_http(address, "POST", "/api/command", &body) {
            Ok((200, _)) => 0,
            Ok((503, _)) | Err(_) => 2,
            Ok(_) => 1,
        };
        counts[slot].fetch_add(1, Ordering::Relaxed);
    }
}

#[test]
#[ignore = "a minute long; .ci/run runs it: cargo test --test panel_load -- --ignored"]
fn the_panel_under_load_keeps_the_rig_on_time_and_its_memory_bounded() {
    let seconds: u64 = std::env::var("TESTRIG_LOAD_S")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(60);
    let out = folder("panel-load");
    let panel = Panel::start(&out, &["--pace", "1"]);
    let pid = panel.child.id();
    let address = panel.address;
    let rss_start = rss_mib(pid);
    let stop = Arc::new(AtomicBool::new(false));
    let messages = Arc::new(AtomicU64::new(0));
    let clients: Vec<_> = (0..WS_CLIENTS)
        .map(|_| {
            let (stop, got) = (Arc::clone(&stop), Arc::clone(&messages));
            std::thread::spawn(move || ws_client(address, stop, got))
        })
        .collect();
    let idle: Vec<TcpStream> = (0..IDLE_SOCKETS)
        .filter_map(|_| TcpStream::connect(address).ok())
        .collect();
    let counts: Arc<[AtomicU64; 3]> = Arc::new(Default::default());
    let flooders: Vec<_> = (0..FLOODERS)
        .map(|_| {
            let (stop, counts) = (Arc::clone(&stop), Arc::clone(&counts));
            std::thread::spawn(move || flooder(address, stop, counts))
        })
        .collect();
    let started = Instant::now();
    let mut rss = Vec::new();
    while started.elapsed() < Duration::from_secs(seconds) {
        std::thread::sleep(Duration::from_secs(1));
        rss.push(rss_mib(pid));
    }
    stop.store(true, Ordering::Relaxed);
    for thread in flooders.into_iter().chain(clients) {
        let _ = thread.join();
    }
    drop(idle);
    let (status, _) = http(address, "GET", "/api/state", "");
    assert_eq!(status, 200, "the server answers after the load");
    let state = panel.state();
    let overruns = state["overruns"].as_u64().expect("overruns");
    let simulated_s = state["simulated_s"].as_f64().expect("simulated_s");
    let peak = rss.iter().copied().fold(f64::NAN, f64::max);
    let half = rss.len() / 2;
    let mean = |r: &[f64]| r.iter().sum::<f64>() / r.len().max(1) as f64;
    let (first_half, second_half) = (mean(&rss[1..half]), mean(&rss[half..]));
    let [ok, refused, no_room] = counts
        .as_ref()
        .each_ref()
        .map(|c| c.load(Ordering::Relaxed));
    let received = messages.load(Ordering::Relaxed);
    println!(
        "panel load, {seconds} s: {WS_CLIENTS} WebSocket clients received {received} states ({:.1} a client a second); {IDLE_SOCKETS} idle sockets; {} commands: {ok} carried out, {refused} refused, {no_room} 503; plant {simulated_s:.1} s simulated, {overruns} overruns; panel RSS {rss_start:.0} MiB at start, {first_half:.0} MiB mean of the first half, {second_half:.0} MiB of the second, {peak:.0} MiB peak",
        received as f64 / (WS_CLIENTS as f64 * seconds as f64),
        ok + refused + no_room,
    );
    assert_eq!(overruns, 0, "the plant fell behind under load");
    assert!(
        received as f64 > 0.5 * 10.0 * (WS_CLIENTS as f64) * seconds as f64,
        "streams starved: {received} states"
    );
    assert!(ok > 100, "commands carried out: {ok}");
    assert!(peak < 400.0, "RSS peak {peak} MiB");
    assert!(
        second_half < 1.2 * first_half + 10.0,
        "RSS grows: {first_half} then {second_half} MiB"
    );
    assert!(
        simulated_s > 0.9 * started.elapsed().as_secs_f64(),
        "{simulated_s} s simulated"
    );
    drop(panel);
    std::fs::remove_dir_all(&out).ok();
}
