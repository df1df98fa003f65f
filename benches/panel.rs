//! The live panel as a whole process (cargo bench --bench panel): `testrig panel` at pace
//! 1 with a client on the state stream (the WebSocket the page reads, ten states a
//! second, each read whole) for `TESTRIG_PANEL_S` seconds (600 unless set), sending a
//! set-speed command every 2 s and timing each from the send to its answer, which comes
//! when the plant's thread has made the new set point act from the start of a block:
//! the command's latency (the frame carrying the new set point is released one block
//! later at pace 1). Then: overruns, lateness p50/p99/max and the CPU share
//! of the whole process, from the session's manifest. With `TESTRIG_PANEL_BROWSER` set to
//! a browser (e.g. /usr/bin/chromium), the page itself is open in it, headless, for the
//! whole run, beside the client.

use std::io::{BufRead, BufReader, Read, Write};
use std::net::{SocketAddr, TcpStream};
use std::process::{Command, Stdio};
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};
use std::time::{Duration, Instant};

fn post(address: SocketAddr, body: &str) -> String {
    let mut stream = TcpStream::connect(address).expect("connects");
    write!(
        stream,
        "POST /api/command HTTP/1.1\r\nHost: {address}\r\nContent-Length: {}\r\nConnection: close\r\n\r\n{body}",
        body.len()
    )
    .expect("sends");
    let mut response = String::new();
    stream.read_to_string(&mut response).expect("reads");
    response
}

/// Reads the state stream until `stop`; counts the states read.
fn watch(address: SocketAddr, stop: &AtomicBool, states: &AtomicU64) {
    let stream = TcpStream::connect(address).expect("connects");
    let url = format!("ws://{address}/api/stream");
    let (mut ws, _) = tungstenite::client(url.as_str(), stream).expect("WebSocket");
    while !stop.load(Ordering::Relaxed) {
        match ws.read() {
            Ok(tungstenite::Message::Text(text)) => {
                let state: serde_json::Value = serde_json::from_str(&text).expect("JSON");
                assert!(state["simulated_s"].is_number());
                states.fetch_add(1, Ordering::Relaxed);
            }
            Ok(_) => {}
            Err(_) => return,
        }
    }
}

fn quantile(sorted: &[f64], q: f64) -> f64 {
    sorted[((sorted.len() - 1) as f64 * q).round() as usize]
}

fn main() {
    let seconds: f64 = std::env::var("TESTRIG_PANEL_S")
        .ok()
        .and_then(|s| s.parse().ok())
        .unwrap_or(600.0);
    let out = std::env::temp_dir().join(format!("testrig-panel-bench-{}", std::process::id()));
    let mut panel = Command::new(env!("CARGO_BIN_EXE_testrig"))
        .args(["panel", "--listen", "127.0.0.1:0", "--pace", "1", "--out"])
        .arg(&out)
        .stdout(Stdio::piped())
        .spawn()
        .expect("the panel starts");
    let mut stdout = BufReader::new(panel.stdout.take().expect("stdout"));
    let mut line = String::new();
    stdout.read_line(&mut line).expect("a line");
    let address: SocketAddr = line
        .split("http://")
        .nth(1)
        .and_then(|r| r.split('/').next())
        .and_then(|a| a.parse().ok())
        .expect("an address");
    let mut browser = std::env::var("TESTRIG_PANEL_BROWSER").ok().map(|program| {
        Command::new(program)
            .args([
                "--headless",
                "--no-sandbox",
                "--disable-gpu",
                "--remote-debugging-port=0",
            ])
            .arg(format!("http://{address}/"))
            .stdout(Stdio::null())
            .stderr(Stdio::null())
            .spawn()
            .expect("the browser starts")
    });
    let stop = Arc::new(AtomicBool::new(false));
    let states = Arc::new(AtomicU64::new(0));
    let watcher = {
        let (stop, states) = (Arc::clone(&stop), Arc::clone(&states));
        std::thread::spawn(move || watch(address, &stop, &states))
    };
    let start = Instant::now();
    let mut latencies_ms = Vec::new();
    let mut k: u64 = 0;
    while start.elapsed().as_secs_f64() < seconds {
        // 2 s apart, shifted by 7 ms each time so that sends fall all over a block.
        std::thread::sleep(Duration::from_millis(2000 + (k * 7 % 20)));
        let rpm = if k.is_multiple_of(2) { 1300 } else { 1250 };
        k += 1;
        let sent = Instant::now();
        let reply = post(address, &format!(r#"{{"cmd": "set_speed", "rpm": {rpm}}}"#));
        latencies_ms.push(sent.elapsed().as_secs_f64() * 1e3);
        assert!(reply.contains("\"ok\":true"), "{reply}");
    }
    let streamed = states.load(Ordering::Relaxed);
    let page = browser.as_mut().map(|b| {
        let alive = matches!(b.try_wait(), Ok(None));
        b.kill().ok();
        b.wait().ok();
        alive
    });
    post(address, r#"{"cmd": "quit"}"#);
    let mut rest = String::new();
    stdout.read_to_string(&mut rest).expect("stdout");
    assert!(panel.wait().expect("ends").success());
    stop.store(true, Ordering::Relaxed);
    watcher.join().ok();
    let manifest: serde_json::Value = serde_json::from_str(
        &std::fs::read_to_string(out.join("manifest.json")).expect("manifest"),
    )
    .expect("JSON");
    latencies_ms.sort_by(f64::total_cmp);
    let wall = start.elapsed().as_secs_f64();
    println!(
        "panel at pace 1 for {:.0} s, a client on the stream ({:.1} states/s), the page open in a browser: {:?}: {} overruns; lateness p50 {:.3} ms, p99 {:.3} ms, max {:.3} ms over {} releases; CPU {:.1} % of one core (whole process)",
        manifest["simulated_s"].as_f64().unwrap_or(0.0),
        streamed as f64 / wall,
        page,
        manifest["overruns"],
        manifest["lateness_ms"]["p50"].as_f64().unwrap_or(f64::NAN),
        manifest["lateness_ms"]["p99"].as_f64().unwrap_or(f64::NAN),
        manifest["lateness_ms"]["max"].as_f64().unwrap_or(f64::NAN),
        manifest["lateness_ms"]["releases"],
        100.0
            * manifest["cpu_share_of_one_core"]
                .as_f64()
                .unwrap_or(f64::NAN),
    );
    println!(
        "set-speed commands ({}), send to answer (the set point acts from the next block's first sample; that block is released one block, 20 ms, later at pace 1): median {:.1} ms, p95 {:.1} ms, max {:.1} ms",
        latencies_ms.len(),
        quantile(&latencies_ms, 0.5),
        quantile(&latencies_ms, 0.95),
        latencies_ms.last().copied().unwrap_or(f64::NAN)
    );
    std::fs::remove_dir_all(&out).ok();
}
