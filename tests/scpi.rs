//! SCPI on the live rig (`testrig panel --scpi`, `docs/scpi.md`) over a raw socket, as a
//! VISA socket session speaks it: identification, settings carried out and journalled,
//! refusals onto the error queue with their numbers and ranges, a measurement waited for
//! with `*OPC?` and read as ASCII and as a definite-length block, 2 000 mangled lines
//! each refused with the rig keeping real time, 50 clients at once, and a client that
//! never reads stalling nobody. pyvisa judges it in `tests/scpi/pyvisa_check.py`.

mod common;
mod panel_support;

use std::io::{BufRead, BufReader, Read, Write};
use std::net::{SocketAddr, TcpStream};
use std::time::{Duration, Instant};

use common::folder;
use panel_support::Panel;
use rand::{RngExt, SeedableRng};
use rand_pcg::Pcg64Mcg;

/// One SCPI client.
struct Client {
    reader: BufReader<TcpStream>,
    writer: TcpStream,
}

impl Client {
    fn connect(address: SocketAddr) -> Self {
        let stream = TcpStream::connect(address).expect("connects");
        stream.set_nodelay(true).expect("no delay");
        stream
            .set_read_timeout(Some(Duration::from_secs(60)))
            .expect("timeout");
        Self {
            reader: BufReader::new(stream.try_clone().expect("clone")),
            writer: stream,
        }
    }

    fn write(&mut self, line: &str) {
        self.writer
            .write_all(format!("{line}\n").as_bytes())
            .expect("writes");
    }

    fn query(&mut self, line: &str) -> String {
        self.write(line);
        let mut answer = String::new();
        self.reader.read_line(&mut answer).expect("an answer");
        answer.trim_end().to_string()
    }

    /// The next error: (number, message).
    fn error(&mut self) -> (i32, String) {
        let answer = self.query("SYST:ERR?");
        let (code, message) = answer.split_once(',').expect("code,message");
        (code.parse().expect("number"), message.to_string())
    }

    fn block(&mut self, line: &str) -> Vec<u8> {
        self.write(line);
        let mut head = [0u8; 2];
        self.reader.read_exact(&mut head).expect("#n");
        assert_eq!(head[0], b'#');
        let digits = usize::from(head[1] - b'0');
        let mut length = vec![0u8; digits];
        self.reader.read_exact(&mut length).expect("length");
        let length: usize = String::from_utf8(length)
            .expect("digits")
            .parse()
            .expect("n");
        let mut bytes = vec![0u8; length + 1];
        self.reader.read_exact(&mut bytes).expect("bytes");
        assert_eq!(bytes.pop(), Some(b'\n'));
        bytes
    }
}

fn start(tag: &str, pace: &str) -> (common::Scratch, Panel, SocketAddr) {
    let dir = folder(tag);
    let mut panel = Panel::start(dir.path(), &["--scpi", "127.0.0.1:0", "--pace", pace]);
    let address = panel.scpi_address();
    (dir, panel, address)
}

#[test]
fn settings_are_carried_out_and_journalled_and_refusals_queued_with_their_numbers() {
    let (dir, panel, address) = start("scpi-basics", "1");
    let mut c = Client::connect(address);
    let idn = c.query("*IDN?");
    assert!(idn.starts_with("testrig,panel"), "{idn}");
    assert_eq!(
        idn.split(',').count(),
        4,
        "manufacturer, model, serial, version"
    );
    assert_eq!(c.error(), (0, "\"No error\"".into()));
    c.write(":RIG:SPEed 900;LOAD 1.5");
    assert_eq!(c.query("rig:spe?;:RIG:LOAD?"), "9E2;1.5E0");
    let state = panel.state();
    assert_eq!(state["speed_set_rpm"], 900.0);
    c.write("RIG:SPE 5000");
    let (code, message) = c.error();
    assert_eq!(code, -222);
    assert!(message.contains("0 to 3000 rev/min"), "{message}");
    assert_eq!(
        c.query("RIG:SPE?"),
        "9E2",
        "a refused value is not carried out"
    );
    for (line, code) in [
        ("RIG:SPED 100", -113),
        ("RIG:SPE", -109),
        ("RIG:SPE 1,2", -108),
        ("RIG:SPE NAN", -104),
        ("RIG:MOT", -113),
        ("WIND:TYPE KAISER", -224),
        ("FREQ:RES 400", -224),
        ("FORM:DATA REAL,16", -224),
    ] {
        c.write(line);
        assert_eq!(c.error().0, code, "{line}");
    }
    assert_eq!(
        c.query("*ESR?"),
        "48",
        "command and execution error bits so far"
    );
    c.write("RIG:SPED 1");
    assert_eq!(
        c.query("*ESR?"),
        "32",
        "read clears: now the command error bit only"
    );
    // Bit 7 (measuring) follows the panel's running average; the rest is ours.
    let stb = |c: &mut Client| c.query("*STB?").parse::<u8>().expect("a byte") & 0x7f;
    assert_eq!(stb(&mut c), 4, "an error waits");
    c.write("*CLS");
    assert_eq!(stb(&mut c), 0);
    assert_eq!(c.query("SYST:ERR:COUN?"), "0");
    c.write("RIG:FILT:TYPE BESS;ORD 4;FREQ 150;:RIG:AMPL:GAIN 250");
    assert_eq!(
        c.query("RIG:FILT:TYPE?;ORD?;FREQ?;:RIG:AMPL:GAIN?"),
        "BESS;4;1.5E2;2.5E2"
    );
    assert_eq!(c.query("SYST:ERR?"), "0,\"No error\"");
    c.write("SCOP:VOLT 0.5;TIME 0.01;MODE SING");
    assert_eq!(
        c.query("SCOP:VOLT?;TIME?;MODE?;:SYST:ERR?"),
        "5E-1;1E-2;SINGLE;0,\"No error\""
    );
    let trace: Vec<f64> = c
        .query("SCOP:DATA?")
        .split(',')
        .map(|t| t.parse().expect("volts"))
        .collect();
    assert!(!trace.is_empty(), "the scope's trace in volts");
    let chain = &panel.state()["chain"];
    assert_eq!(chain["filter"]["kind"], "bessel", "{chain}");
    let session = std::fs::read_to_string(dir.path().join("session.toml")).expect("session");
    assert!(
        session.contains("cmd = \"set_speed\"") && session.contains("rpm = 900.0"),
        "{session}"
    );
    assert!(!session.contains("5000"), "refused commands stay out");
}

#[test]
fn a_measurement_is_waited_for_and_read_as_text_and_as_a_block() {
    // Pace 20: the rig settles 30 s (1.5 s of wall time), then 16 averages of 1.28 s
    // take about 1 s, long beside the query that finds the measurement running.
    let (_dir, _panel, address) = start("scpi-measure", "20");
    let mut c = Client::connect(address);
    c.write("SENS:FREQ:SPAN 200;RES 256;:AVER:COUN 16;:WIND HANN");
    assert_eq!(
        c.query("FREQ:SPAN?;RES?;:AVER:COUN?;:WIND?"),
        "2E2;2.56E2;16;HANN"
    );
    while c.query("RIG:TIME?").parse::<f64>().expect("seconds") < 30.0 {
        std::thread::sleep(Duration::from_millis(20));
    }
    c.write("INIT");
    assert_eq!(c.query("STAT:OPER:COND?"), "16", "measuring");
    assert_eq!(c.query("*OPC?"), "1");
    assert_eq!(c.query("STAT:OPER:COND?"), "0");
    let text: Vec<f64> = c
        .query("CALC:DATA?")
        .split(',')
        .map(|t| t.parse().expect("number"))
        .collect();
    let frequencies: Vec<f64> = c
        .query("CALC:X:DATA?")
        .split(',')
        .map(|t| t.parse().expect("number"))
        .collect();
    assert_eq!(text.len(), frequencies.len());
    let df = frequencies[1] - frequencies[0];
    assert!((df - 200.0 / 256.0).abs() < 1e-12, "256 lines in 200 Hz");
    c.write("FORM REAL,64");
    let bytes = c.block("CALC:DATA?");
    let real: Vec<f64> = bytes
        .chunks(8)
        .map(|b| f64::from_be_bytes(b.try_into().expect("8 bytes")))
        .collect();
    assert_eq!(real, text, "the same spectrum in both formats");
    c.write("FORM REAL,32");
    let bytes = c.block("CALC:DATA?");
    assert_eq!(bytes.len(), 4 * text.len());
    // The motion at 1300 rev/min and 2.712 N m is period 2: the half-order line (10.83 Hz)
    // stands far above the lines around it.
    let half = frequencies
        .iter()
        .position(|f| (f - 1300.0 / 120.0).abs() <= df / 2.0)
        .expect("a line at the half order");
    let peak = text[half - 1..=half + 1]
        .iter()
        .cloned()
        .fold(0.0, f64::max);
    let around = text[half + 4..half + 8].iter().cloned().fold(0.0, f64::max);
    assert!(
        peak > 100.0 * around,
        "half order {peak} V² against {around} V² around it"
    );
}

/// A mangled line certain to be refused, from a seeded generator; three kinds of the
/// thirteen carry a character beyond ASCII or a control byte in the header, a string or a number.
fn mangled(rng: &mut Pcg64Mcg, k: usize) -> String {
    let headers = [
        "RIG:SPE",
        "RIG:LOAD",
        "FREQ:SPAN",
        "AVER:COUN",
        "INP:RANG",
        "RIG:OSC:FREQ",
    ];
    let header = headers[rng.random_range(0..headers.len())];
    let beyond_ascii = ["É", "≥", "µε", "\u{7f}", "\u{85}", "…", "😀"];
    let odd = beyond_ascii[rng.random_range(0..beyond_ascii.len())];
    match k % 13 {
        0 => format!("QZ{}:{}", rng.random::<u32>(), header),
        10 => format!("{header}{odd} 1"),
        11 => format!("{header} \"{odd}\""),
        12 => format!("{header} {odd}5"),
        1 => format!("{header} 1e{}", rng.random_range(30..400)),
        2 => format!("{header} NaN"),
        3 => format!("{header} {}", -rng.random_range(1.0..1e6_f64)),
        4 => {
            let bytes: Vec<u8> = (0..rng.random_range(1..64))
                .map(|_| rng.random_range(0u8..32))
                .collect();
            format!(
                "{header} {}",
                String::from_utf8_lossy(&bytes).replace('\n', "\u{1}")
            )
        }
        5 => header.to_string(),
        6 => format!("{header} 1,2,3"),
        7 => format!("{header}? 5"),
        8 => format!("{header} \"unterminated"),
        _ => format!("*{}?", "X".repeat(rng.random_range(1..30))),
    }
}

#[test]
fn mangled_lines_are_each_refused_and_the_rig_keeps_real_time() {
    let (_dir, panel, address) = start("scpi-fuzz", "1");
    let mut c = Client::connect(address);
    let mut rng = Pcg64Mcg::seed_from_u64(37);
    for k in 0..2000 {
        let line = mangled(&mut rng, k);
        c.write(&line);
        let (code, message) = c.error();
        assert!(code < 0, "{line:?} was not refused");
        assert!(
            message.bytes().all(|b| (0x20..0x7f).contains(&b)),
            "{line:?}: the answer {message:?} is not printable 7-bit ASCII (IEEE 488.2)"
        );
        assert_eq!(
            c.error().0,
            0,
            "{line:?} left more than one error: {message}"
        );
    }
    let huge = "RIG:SPE ".to_string() + &"9".repeat(1 << 20);
    c.write(&huge);
    assert_eq!(c.error().0, -363, "a 1 MB line");
    c.writer
        .write_all(&[0xff, 0xfe, 0x00, b'\n'])
        .expect("binary");
    assert_eq!(c.error().0, -102, "bytes that are not text");
    assert!(c.query("*IDN?").starts_with("testrig"));
    let state = panel.state();
    assert_eq!(state["overruns"], 0, "the rig kept real time: {state}");
    assert_eq!(
        state["speed_set_rpm"], 1300.0,
        "nothing mangled was carried out"
    );
}

#[test]
fn fifty_clients_are_served_at_once_and_one_that_never_reads_stalls_nobody() {
    let (_dir, panel, address) = start("scpi-clients", "1");
    // A client that sends queries and never reads its answers.
    let mut silent = TcpStream::connect(address).expect("connects");
    let flood = "*IDN?;RIG:SPE?;RIG:LOAD?;RIG:TIME?\n".repeat(2000);
    let writer = std::thread::spawn(move || {
        let _ = silent.set_write_timeout(Some(Duration::from_secs(20)));
        for _ in 0..50 {
            if silent.write_all(flood.as_bytes()).is_err() {
                break;
            }
        }
        silent
    });
    std::thread::sleep(Duration::from_millis(300));
    let started = Instant::now();
    let handles: Vec<_> = (0..50)
        .map(|k| {
            std::thread::spawn(move || {
                let mut c = Client::connect(address);
                for _ in 0..20 {
                    assert!(c.query("*IDN?").starts_with("testrig"));
                    assert_eq!(c.query("RIG:SPE?"), "1.3E3", "client {k}");
                }
            })
        })
        .collect();
    for h in handles {
        h.join().expect("a client");
    }
    let took = started.elapsed();
    println!("50 clients × 40 queries beside a silent client: {took:?}");
    assert!(
        took < Duration::from_secs(10),
        "50 clients × 40 queries took {took:?}"
    );
    let state = panel.state();
    assert_eq!(state["overruns"], 0, "{state}");
    drop(writer.join());
}

#[test]
fn beyond_loopback_only_the_token_unlocks_the_rig() {
    let dir = folder("scpi-token");
    let mut panel = Panel::start(dir.path(), &["--scpi", "0.0.0.0:0", "--pace", "1"]);
    let (address, token) = panel.scpi();
    let token = token.expect("a token is printed beyond loopback");
    let mut c = Client::connect(SocketAddr::from(([127, 0, 0, 1], address.port())));
    assert!(
        c.query("*IDN?").starts_with("testrig"),
        "identification is open"
    );
    c.write("RIG:SPE 900");
    assert_eq!(c.error().0, -203);
    c.write("SYST:PASS \"not-the-token\"");
    assert_eq!(c.error().0, -203);
    c.write(&format!("SYST:PASS \"{token}\""));
    c.write("RIG:SPE 900");
    assert_eq!(c.query("RIG:SPE?;:SYST:ERR?"), "9E2;0,\"No error\"");
    assert_eq!(panel.state()["speed_set_rpm"], 900.0);
}

#[test]
#[ignore = "needs Python modules (python3 -m pip install -r tests/requirements.txt); run by .ci/run"]
fn pyvisa_drives_the_rig() {
    common::run_python_check(
        "scpi/pyvisa_check.py",
        "scpi-pyvisa",
        &["pyvisa", "pyvisa_py", "numpy", "matplotlib"],
    );
}
