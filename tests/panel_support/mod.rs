//! A panel started for a test, and a plain HTTP client for its API.
#![allow(dead_code)]

use std::io::{BufRead, BufReader, Read, Write};
use std::net::{SocketAddr, TcpStream};
use std::path::Path;
use std::process::{Child, Command, Stdio};
use std::time::{Duration, Instant};

/// A running `testrig panel`.
pub struct Panel {
    /// The process.
    pub child: Child,
    /// Where it serves.
    pub address: SocketAddr,
    /// The token its URL carries (bound beyond loopback).
    pub token: Option<String>,
    /// Its standard output after the first line (kept open: the panel prints at the end).
    stdout: BufReader<std::process::ChildStdout>,
}

impl Panel {
    /// Starts a panel on a free loopback port with `args` besides `--listen` and `--out`.
    pub fn start(out: &Path, args: &[&str]) -> Self {
        Self::start_on("127.0.0.1:0", out, args)
    }

    /// Starts a panel listening on `listen` with `args` besides `--listen` and `--out`.
    pub fn start_on(listen: &str, out: &Path, args: &[&str]) -> Self {
        let mut child = Command::new(env!("CARGO_BIN_EXE_testrig"))
            .args(["panel", "--listen", listen, "--out"])
            .arg(out)
            .args(args)
            .stdout(Stdio::piped())
            .stderr(Stdio::piped())
            .spawn()
            .expect("the panel starts");
        let stdout = child.stdout.take().expect("stdout");
        let mut stdout = BufReader::new(stdout);
        let mut line = String::new();
        stdout.read_line(&mut line).expect("a first line");
        let address = line
            .split("http://")
            .nth(1)
            .and_then(|rest| rest.split('/').next())
            .and_then(|a| a.parse().ok())
            .unwrap_or_else(|| panic!("no address in {line:?}"));
        let token = line
            .split("?token=")
            .nth(1)
            .and_then(|rest| rest.split_whitespace().next())
            .map(str::to_string);
        Self {
            child,
            address,
            token,
            stdout,
        }
    }

    /// The next line the panel prints (after the first, its URL).
    pub fn next_line(&mut self) -> String {
        let mut line = String::new();
        self.stdout.read_line(&mut line).expect("a line");
        line
    }

    /// The SCPI server's socket address, from the line `--scpi` makes it print next.
    pub fn scpi_address(&mut self) -> SocketAddr {
        self.scpi().0
    }

    /// The SCPI server's socket address and its token (bound beyond loopback), from the
    /// line `--scpi` makes it print next.
    pub fn scpi(&mut self) -> (SocketAddr, Option<String>) {
        let line = self.next_line();
        let token = line
            .split("SYSTem:PASSword \"")
            .nth(1)
            .and_then(|rest| rest.split('"').next())
            .map(str::to_string);
        let visa = line
            .split("TCPIP::")
            .nth(1)
            .unwrap_or_else(|| panic!("no SCPI address in {line:?}"));
        let mut parts = visa.split("::");
        let host = parts.next().expect("host");
        let port = parts.next().expect("port");
        (format!("{host}:{port}").parse().expect("address"), token)
    }

    /// `GET path`: (status, body).
    pub fn get(&self, path: &str) -> (u16, String) {
        http(self.address, "GET", path, "")
    }

    /// `POST /api/command` with `body`: (status, reply as JSON).
    pub fn command(&self, body: &str) -> (u16, serde_json::Value) {
        let (status, text) = http(self.address, "POST", "/api/command", body);
        let reply = serde_json::from_str(&text).unwrap_or_else(|e| panic!("{e}: {text}"));
        (status, reply)
    }

    /// The panel's state.
    pub fn state(&self) -> serde_json::Value {
        let (status, text) = self.get("/api/state");
        assert_eq!(status, 200, "{text}");
        serde_json::from_str(&text).unwrap_or_else(|e| panic!("{e}: {text:?}"))
    }

    /// Waits (at most `limit`) until `ready` holds of the state; returns that state.
    pub fn wait_for(
        &self,
        limit: Duration,
        ready: impl Fn(&serde_json::Value) -> bool,
    ) -> serde_json::Value {
        let start = Instant::now();
        loop {
            let state = self.state();
            if ready(&state) {
                return state;
            }
            assert!(
                start.elapsed() < limit,
                "not reached within {limit:?}: {state}"
            );
            std::thread::sleep(Duration::from_millis(50));
        }
    }

    /// Waits for the process to end; its exit status and stdout and stderr.
    pub fn wait(mut self) -> (std::process::ExitStatus, String) {
        let mut stderr = String::new();
        self.stdout.read_to_string(&mut stderr).expect("stdout");
        let status = self.child.wait().expect("ends");
        if let Some(mut e) = self.child.stderr.take() {
            e.read_to_string(&mut stderr).expect("stderr");
        }
        (status, stderr)
    }
}

impl Drop for Panel {
    /// A test that fails part-way leaves no panel running.
    fn drop(&mut self) {
        if matches!(self.child.try_wait(), Ok(None)) {
            let _ = self.child.kill();
            let _ = self.child.wait();
        }
    }
}

/// One HTTP/1.1 request, the connection closed after it: status and body.
pub fn http(address: SocketAddr, method: &str, path: &str, body: &str) -> (u16, String) {
    try_http(address, method, path, body).expect("an HTTP exchange")
}

/// [`http`], its failure returned (a server that closes a connection it has no room for
/// may do so before the request is written).
pub fn try_http(
    address: SocketAddr,
    method: &str,
    path: &str,
    body: &str,
) -> std::io::Result<(u16, String)> {
    let headers = format!("Host: {address}\r\nContent-Type: application/json\r\n");
    let response = try_http_with(address, method, path, &headers, body)?;
    let status = response
        .split_whitespace()
        .nth(1)
        .and_then(|s| s.parse().ok())
        .unwrap_or(0);
    let body = response
        .split_once("\r\n\r\n")
        .map_or(String::new(), |(_, b)| b.to_string());
    Ok((status, body))
}

/// One HTTP/1.1 request, the connection closed after it: the whole response as text.
pub fn http_response(address: SocketAddr, method: &str, path: &str, body: &str) -> String {
    let headers = format!("Host: {address}\r\nContent-Type: application/json\r\n");
    http_with(address, method, path, &headers, body)
}

/// One HTTP/1.1 request with the header lines `headers` (each ending in CRLF): the whole
/// response as text.
pub fn http_with(
    address: SocketAddr,
    method: &str,
    path: &str,
    headers: &str,
    body: &str,
) -> String {
    try_http_with(address, method, path, headers, body).expect("an HTTP exchange")
}

/// [`http_with`], its failure returned.
fn try_http_with(
    address: SocketAddr,
    method: &str,
    path: &str,
    headers: &str,
    body: &str,
) -> std::io::Result<String> {
    let mut stream = TcpStream::connect(address)?;
    stream.set_read_timeout(Some(Duration::from_secs(30)))?;
    write!(
        stream,
        "{method} {path} HTTP/1.1\r\n{headers}Content-Length: {}\r\nConnection: close\r\n\r\n{body}",
        body.len()
    )?;
    let mut response = String::new();
    stream.read_to_string(&mut response)?;
    Ok(response)
}
