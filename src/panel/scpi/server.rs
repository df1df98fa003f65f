//! The SCPI server: a raw socket (VISA's `TCPIP::host::port::SOCKET`), newline-terminated
//! lines, one thread and one [`Instrument`] per client, at most [`MAX_CLIENTS`] at once.
//! A line longer than `MAX_LINE_BYTES` is read to its end and refused (-363); a client
//! that does not read its answers is dropped after [`WRITE_TIMEOUT`], stalling only its
//! own thread; the rig's thread never waits for a client.

use std::io::{ErrorKind, Read, Write};
use std::net::{SocketAddr, TcpListener, TcpStream};
use std::sync::Arc;
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::thread::JoinHandle;
use std::time::Duration;

use super::error::ScpiError;
use super::instrument::Instrument;
use super::message::MAX_LINE_BYTES;
use super::rack::Rack;
use crate::panel::guard::Guard;

/// Most clients served at once; one more is closed at once.
pub const MAX_CLIENTS: usize = 64;
/// Time a client has to take an answer before it is dropped.
const WRITE_TIMEOUT: Duration = Duration::from_secs(5);
/// How often a waiting thread looks whether the server stops.
const POLL: Duration = Duration::from_millis(50);

/// The running SCPI server.
pub struct ScpiServer {
    /// The address it listens on.
    pub address: SocketAddr,
    /// The token protected commands wait for, when bound beyond loopback.
    pub token: Option<String>,
    stop: Arc<AtomicBool>,
    thread: Option<JoinHandle<()>>,
}

impl ScpiServer {
    /// Listens on `address` for clients of `rack` until [`ScpiServer::shut_down`]; beyond
    /// loopback every command but `*IDN?`, `SYSTem:ERRor?` and `SYSTem:PASSword` waits for
    /// the token (`docs/security.md`).
    pub fn start(address: SocketAddr, mut rack: Rack) -> anyhow::Result<Self> {
        let cannot = |e: std::io::Error| anyhow::anyhow!("--scpi {address}: cannot listen: {e}");
        let listener = TcpListener::bind(address).map_err(cannot)?;
        let address = listener.local_addr().map_err(cannot)?;
        listener.set_nonblocking(true).map_err(cannot)?;
        let token = Guard::new(address)
            .map_err(|e| anyhow::anyhow!("cannot draw the SCPI token: {e}"))?
            .token()
            .map(str::to_string);
        rack.token = token.clone();
        let stop = Arc::clone(&rack.stop);
        let thread = std::thread::Builder::new()
            .name("scpi".into())
            .spawn(move || accept(&listener, &rack))?;
        Ok(Self {
            address,
            token,
            stop,
            thread: Some(thread),
        })
    }

    /// Stops listening and lets every client's thread end.
    pub fn shut_down(mut self) {
        self.stop.store(true, Ordering::Relaxed);
        if let Some(thread) = self.thread.take() {
            let _ = thread.join();
        }
    }
}

fn accept(listener: &TcpListener, rack: &Rack) {
    let clients = Arc::new(AtomicUsize::new(0));
    while !rack.stop.load(Ordering::Relaxed) {
        match listener.accept() {
            Ok((stream, _)) => {
                if clients.load(Ordering::Relaxed) >= MAX_CLIENTS {
                    drop(stream);
                    continue;
                }
                clients.fetch_add(1, Ordering::Relaxed);
                let (rack, count) = (rack.clone(), Arc::clone(&clients));
                let spawned = std::thread::Builder::new()
                    .name("scpi-client".into())
                    .spawn(move || {
                        serve(stream, rack);
                        count.fetch_sub(1, Ordering::Relaxed);
                    });
                if spawned.is_err() {
                    clients.fetch_sub(1, Ordering::Relaxed);
                }
            }
            Err(e) if e.kind() == ErrorKind::WouldBlock => std::thread::sleep(POLL),
            Err(_) => std::thread::sleep(POLL),
        }
    }
}

/// Serves one client until it closes, stops reading, or the server stops.
fn serve(mut stream: TcpStream, rack: Rack) {
    let setup = stream
        .set_nonblocking(false)
        .and_then(|()| stream.set_read_timeout(Some(POLL)))
        .and_then(|()| stream.set_write_timeout(Some(WRITE_TIMEOUT)))
        .and_then(|()| stream.set_nodelay(true));
    if setup.is_err() {
        return;
    }
    let stop = Arc::clone(&rack.stop);
    let mut instrument = Instrument::new(rack);
    let mut line: Vec<u8> = Vec::new();
    let mut overrun = false;
    let mut buffer = [0u8; 8192];
    while !stop.load(Ordering::Relaxed) {
        let n = match stream.read(&mut buffer) {
            Ok(0) => return,
            Ok(n) => n,
            Err(e) if matches!(e.kind(), ErrorKind::WouldBlock | ErrorKind::TimedOut) => continue,
            Err(e) if e.kind() == ErrorKind::Interrupted => continue,
            Err(_) => return,
        };
        for &byte in &buffer[..n] {
            if byte != b'\n' {
                if line.len() < MAX_LINE_BYTES {
                    line.push(byte);
                } else {
                    overrun = true;
                }
                continue;
            }
            let answer = if std::mem::take(&mut overrun) {
                instrument.push_error(ScpiError::input_overrun(&format!(
                    "a line over {MAX_LINE_BYTES} bytes, refused whole"
                )));
                Vec::new()
            } else {
                answer_line(&mut instrument, &line)
            };
            line.clear();
            if !answer.is_empty() && stream.write_all(&answer).is_err() {
                return;
            }
        }
    }
}

/// The answer to one line of bytes (a carriage return before the newline dropped).
fn answer_line(instrument: &mut Instrument, bytes: &[u8]) -> Vec<u8> {
    let bytes = bytes.strip_suffix(b"\r").unwrap_or(bytes);
    match std::str::from_utf8(bytes) {
        Ok(text) if !text.chars().any(|c| c.is_control() && c != '\t') => instrument.execute(text),
        _ => {
            instrument.push_error(ScpiError::syntax("a line that is not printable text"));
            Vec::new()
        }
    }
}
