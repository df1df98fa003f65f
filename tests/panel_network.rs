//! The panel's server under an attacker's or a careless client's load (issue 23, items 3
//! and 5): a flood of idle connections, a head too large to keep, a client that never
//! finishes, and HTTP and WebSocket requests fuzzed. The server keeps serving, the rig
//! keeps running, and nothing grows without bound.

mod common;
mod panel_support;

use std::io::{Read, Write};
use std::net::TcpStream;
use std::time::{Duration, Instant};

use common::folder;
use panel_support::{Panel, http_with};
use proptest::prelude::*;
use testrig::panel::{MAX_BODY_BYTES, MAX_CONNECTIONS, RequestError, read_request_from};

/// The simulated time of the rig (s).
fn rig_time_s(panel: &Panel) -> f64 {
    panel.state()["simulated_s"].as_f64().expect("simulated_s")
}

/// Status of a response read whole from `conn` (0 if none came).
fn status_of(conn: &mut TcpStream) -> u16 {
    let mut text = String::new();
    let _ = conn.read_to_string(&mut text);
    text.split_whitespace()
        .nth(1)
        .and_then(|s| s.parse().ok())
        .unwrap_or(0)
}

/// 700 idle connections (188 beyond the cap) opened at once. The server answers every
/// one beyond its cap 503 at once, times the idle ones out (408 after 5 s), and serves
/// again as soon as they are gone; the rig runs on at its pace throughout. Before, each
/// idle connection held a thread forever and 10 000 of them ended the server.
#[test]
fn a_flood_of_idle_connections_neither_stops_the_server_nor_the_rig() {
    let out = folder("panel-flood");
    let panel = Panel::start(&out, &["--pace", "1"]);
    let t0 = rig_time_s(&panel);
    let wall = Instant::now();
    let mut flood: Vec<TcpStream> = (0..MAX_CONNECTIONS + 188)
        .filter_map(|_| TcpStream::connect(panel.address).ok())
        .collect();
    assert!(flood.len() > MAX_CONNECTIONS, "{} connected", flood.len());
    // While the flood holds every place, a request is answered at once: 503 or served.
    let started = Instant::now();
    let (status, _) = panel_support::http(panel.address, "GET", "/api/state", "");
    assert!(
        status == 503 || status == 200,
        "status {status} during the flood"
    );
    assert!(started.elapsed() < Duration::from_secs(2));
    // The idle connections are answered and closed: 503 beyond the cap, 408 within it.
    let mut statuses = std::collections::BTreeMap::new();
    for conn in &mut flood {
        conn.set_read_timeout(Some(Duration::from_secs(10)))
            .expect("timeout");
        *statuses.entry(status_of(conn)).or_insert(0) += 1;
    }
    assert!(
        statuses.get(&408).copied().unwrap_or(0) <= MAX_CONNECTIONS
            && statuses.get(&503).copied().unwrap_or(0) + MAX_CONNECTIONS >= flood.len(),
        "{statuses:?}"
    );
    assert!(
        statuses.keys().all(|s| [408, 503].contains(s)),
        "{statuses:?}"
    );
    drop(flood);
    // Served again at once, and the rig kept its pace (real time) through the flood.
    let state = panel.wait_for(Duration::from_secs(2), |_| true);
    let advanced_s = state["simulated_s"].as_f64().expect("simulated_s") - t0;
    let elapsed_s = wall.elapsed().as_secs_f64();
    assert!(
        advanced_s > 0.8 * elapsed_s - 0.5,
        "the rig advanced {advanced_s} s in {elapsed_s} s of wall time"
    );
    drop(panel);
    std::fs::remove_dir_all(&out).ok();
}

/// A head of 1 MB (the server once read 400 MB whole) is refused 431 after 16 KiB; a body
/// over 64 KiB 413; a chunked body 411; a client that sends half a request is answered
/// 408 within the 5 s deadline, however slowly it trickles.
#[test]
fn oversized_and_unfinished_requests_are_refused_with_their_status() {
    let out = folder("panel-bounds");
    let panel = Panel::start(&out, &["--pace", "1"]);
    let mut conn = TcpStream::connect(panel.address).expect("connects");
    conn.set_read_timeout(Some(Duration::from_secs(10)))
        .expect("timeout");
    let mut writer = conn.try_clone().expect("clone");
    let sender = std::thread::spawn(move || {
        let line = format!("X-Filler: {}\r\n", "a".repeat(1000));
        let _ = writer.write_all(b"GET /api/state HTTP/1.1\r\n");
        for _ in 0..1000 {
            if writer.write_all(line.as_bytes()).is_err() {
                break;
            }
        }
    });
    assert_eq!(status_of(&mut conn), 431);
    let _ = sender.join();

    let big = format!("{{\"cmd\":\"set_speed\",\"rpm\":{}}}", "1".repeat(70_000));
    let response = http_with(
        panel.address,
        "POST",
        "/api/command",
        &format!(
            "Host: {}\r\nContent-Type: application/json\r\n",
            panel.address
        ),
        &big,
    );
    assert!(response.starts_with("HTTP/1.1 413"), "{response:.80}");

    let mut chunked = TcpStream::connect(panel.address).expect("connects");
    write!(
        chunked,
        "POST /api/command HTTP/1.1\r\nHost: {}\r\nTransfer-Encoding: chunked\r\n\r\n5\r\nhello\r\n",
        panel.address
    )
    .expect("sends");
    assert_eq!(status_of(&mut chunked), 411);

    let mut slow = TcpStream::connect(panel.address).expect("connects");
    slow.set_read_timeout(Some(Duration::from_millis(300)))
        .expect("timeout");
    let started = Instant::now();
    let mut answer = Vec::new();
    for byte in b"GET /api/state HTTP/1.1\r\nHost: x".iter().cycle() {
        if slow.write_all(&[*byte]).is_err() || started.elapsed() > Duration::from_secs(8) {
            break;
        }
        let mut buf = [0u8; 512];
        if let Ok(n) = slow.read(&mut buf) {
            answer.extend_from_slice(&buf[..n]);
            break;
        }
    }
    let answer = String::from_utf8_lossy(&answer);
    assert!(answer.starts_with("HTTP/1.1 408"), "{answer:?}");
    let waited = started.elapsed();
    assert!(
        waited > Duration::from_secs(4) && waited < Duration::from_secs(7),
        "{waited:?}"
    );
    // And the server serves on.
    assert_eq!(panel.get("/api/state").0, 200);
    drop(panel);
    std::fs::remove_dir_all(&out).ok();
}

/// A request line, header lines and a body as a client might mangle them.
fn request_bytes() -> impl Strategy<Value = Vec<u8>> {
    let method = prop::sample::select(vec!["GET", "POST", "HEAD", "OPTIONS", "G\0T", ""]);
    let path = prop::sample::select(vec![
        "/",
        "/api/state",
        "/api/command",
        "/api/stream",
        "/api/command?token=x",
        "*",
        "/%00",
    ]);
    let header = (
        prop::sample::select(vec![
            "Host",
            "Content-Length",
            "Content-Type",
            "Origin",
            "Transfer-Encoding",
            "Sec-WebSocket-Key",
            "Upgrade",
            "X\u{0}",
        ]),
        prop::sample::select(vec![
            "127.0.0.1",
            "application/json",
            "-1",
            "18446744073709551616",
            "5",
            "chunked",
            "websocket",
            "dGhlIHNhbXBsZSBub25jZQ==",
            "",
        ]),
    );
    (
        method,
        path,
        prop::collection::vec(header, 0..6),
        prop::collection::vec(any::<u8>(), 0..64),
        any::<bool>(),
    )
        .prop_map(|(method, path, headers, body, cut)| {
            let mut text = format!("{method} {path} HTTP/1.1\r\n");
            for (name, value) in headers {
                text.push_str(&format!("{name}: {value}\r\n"));
            }
            text.push_str("\r\n");
            let mut bytes = text.into_bytes();
            bytes.extend(body);
            if cut {
                bytes.truncate(bytes.len() / 2);
            }
            bytes
        })
}

proptest! {
    #![proptest_config(ProptestConfig { cases: 2000, ..ProptestConfig::default() })]

    /// Any bytes, and any mangled request, are read or refused without a panic; a refusal
    /// that the client can still read carries a 4xx status, and nothing read exceeds the
    /// bounds.
    #[test]
    fn any_request_bytes_are_read_or_refused(
        bytes in prop_oneof![request_bytes(), prop::collection::vec(any::<u8>(), 0..300)]
    ) {
        match read_request_from(&mut &bytes[..], |_| Ok(())) {
            Ok(request) => {
                prop_assert!(request.body.len() <= MAX_BODY_BYTES);
                prop_assert!(request.body.len() <= bytes.len());
            }
            Err(RequestError::Closed) => prop_assert!(bytes.is_empty()),
            Err(e) => {
                let status = e.status().unwrap_or(0);
                prop_assert!((400..500).contains(&status), "{e}: {status}");
            }
        }
    }
}

/// Mangled requests sent to a running panel, the WebSocket handshake among them: each is
/// answered or closed, none kills the server, and the rig runs on.
#[test]
fn fuzzed_requests_to_a_live_panel_are_answered_or_closed() {
    let out = folder("panel-fuzz");
    let panel = Panel::start(&out, &["--pace", "100"]);
    let mut runner = proptest::test_runner::TestRunner::new(ProptestConfig {
        cases: 200,
        ..ProptestConfig::default()
    });
    let address = panel.address;
    runner
        .run(&request_bytes(), |bytes| {
            let mut conn = TcpStream::connect(address).expect("connects");
            conn.set_read_timeout(Some(Duration::from_secs(8)))
                .expect("timeout");
            conn.write_all(&bytes).expect("sends");
            let _ = conn.shutdown(std::net::Shutdown::Write);
            // Read the status line (a stream, once upgraded, would send on for ever).
            let mut answer = Vec::new();
            let mut buf = [0u8; 256];
            while !answer.windows(2).any(|w| w == b"\r\n") {
                match conn.read(&mut buf) {
                    Ok(0) | Err(_) => break,
                    Ok(n) => answer.extend_from_slice(&buf[..n]),
                }
            }
            let text = String::from_utf8_lossy(&answer);
            prop_assert!(
                text.is_empty() || text.starts_with("HTTP/1.1 "),
                "{text:.120}"
            );
            Ok(())
        })
        .expect("every request answered or closed");
    assert_eq!(panel.get("/api/state").0, 200);
    drop(panel);
    std::fs::remove_dir_all(&out).ok();
}

/// A command as JSON a script might mangle: a known or unknown `cmd`, and fields of every
/// JSON kind with edge values.
fn command_json() -> impl Strategy<Value = String> {
    let cmd = prop::sample::select(vec![
        "set_speed",
        "set_load",
        "set_oscillating_load",
        "set_amplifier_gain",
        "set_filter",
        "set_adc_range",
        "set_analyser",
        "set_scope",
        "start_average",
        "hold_average",
        "arm_scope",
        "record",
        "save_displays",
        "quit_not",
        "",
    ]);
    let field = prop::sample::select(vec![
        "rpm",
        "nm",
        "hz",
        "gain",
        "kind",
        "order",
        "cutoff_hz",
        "range_v",
        "fmax_hz",
        "block",
        "window",
        "averages",
        "overlap_pct",
        "volts_per_div",
        "seconds_per_div",
        "trigger_v",
        "mode",
        "on",
    ]);
    let value = prop::sample::select(vec![
        "0",
        "-1",
        "1e308",
        "-1e308",
        "5e-324",
        "1300",
        "2.712",
        "18446744073709551616",
        "4294967297",
        "true",
        "null",
        "\"butterworth\"",
        "\"hanning\"",
        "\"auto\"",
        "\"\"",
        "[]",
        "{}",
    ]);
    (cmd, prop::collection::vec((field, value), 0..5)).prop_map(|(cmd, fields)| {
        let mut text = format!("{{\"cmd\": \"{cmd}\"");
        for (name, value) in fields {
            text.push_str(&format!(", \"{name}\": {value}"));
        }
        text.push('}');
        text
    })
}

/// 300 mangled commands sent to a live panel through its API: each is carried out (200)
/// or refused (400) with a JSON reply, none crashes the rig, which runs on.
#[test]
fn fuzzed_json_commands_are_carried_out_or_refused() {
    let out = folder("panel-json-fuzz");
    let panel = Panel::start(&out, &["--pace", "100"]);
    let mut runner = proptest::test_runner::TestRunner::new_with_rng(
        ProptestConfig {
            cases: 300,
            failure_persistence: None,
            ..ProptestConfig::default()
        },
        proptest::test_runner::TestRng::from_seed(
            proptest::test_runner::RngAlgorithm::ChaCha,
            &[23; 32],
        ),
    );
    let carried_out = std::cell::Cell::new(0);
    runner
        .run(&command_json(), |body| {
            let (status, reply) = panel.command(&body);
            prop_assert!(status == 200 || status == 400, "{body}: {status} {reply}");
            prop_assert_eq!(reply["ok"].as_bool(), Some(status == 200), "{}", body);
            if status == 200 {
                carried_out.set(carried_out.get() + 1);
            }
            Ok(())
        })
        .expect("every command answered");
    assert!(carried_out.get() > 0, "the generator reaches the rig");
    let before = panel.state()["simulated_s"].as_f64().expect("time");
    std::thread::sleep(Duration::from_millis(300));
    let after = panel.state()["simulated_s"].as_f64().expect("time");
    assert!(after > before, "the rig stopped at {before} s");
    drop(panel);
    std::fs::remove_dir_all(&out).ok();
}
